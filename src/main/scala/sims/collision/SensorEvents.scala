package sims.collision

import sims.dynamics.Shape

/** A shape that began to overlap a sensor in the last step (see [[SensorEvents]]).
  *
  * @param sensor the sensor shape
  * @param visitor the shape that came in
  */
final case class SensorBegin(sensor: Shape, visitor: Shape)

/** A shape that stopped overlapping a sensor in the last step, or can no longer be seen by it
  * (either left the world, stopped colliding or changed its sensor flag): the end of the pair's
  * [[SensorBegin]].
  *
  * @param sensor the sensor shape
  * @param visitor the shape that went out
  */
final case class SensorEnd(sensor: Shape, visitor: Shape)

/** The sensor events of a world's last step (`World.sensorEvents`): the shapes that began to
  * overlap a sensor shape (`Shape.sensor`) and those that stopped, in world order (by the
  * sensor's join order, then the visitor's). Paired like contact events: every begin is followed
  * by exactly one end in a later step, also when a shape leaves the world, stops colliding,
  * changes its filter bits or its sensor flag.
  *
  * A sensor sees the shapes of other bodies that overlap it (the narrowphase's test, touching
  * included) at the end of the step, if they are collidable, not sensors themselves and accepted
  * by the filters (categories and masks, groups, `transientShapes`, joints' `collideConnected`),
  * fixed ones too unless the sensor's body is fixed as well. It never pushes nor is pushed.
  *
  * The collections are refilled by the next step (see [[ContactEvents]]).
  */
final class SensorEvents private[sims] (tracker: PairTracker) extends TrackedEvents[SensorBegin, SensorEnd](tracker):

  /** The shapes that began to overlap a sensor in the last step. */
  def begins: collection.IndexedSeq[SensorBegin] = beginsOfLastStep

  /** The shapes that stopped overlapping a sensor in the last step. */
  def ends: collection.IndexedSeq[SensorEnd] = endsOfLastStep

  /** Every (sensor, visitor) pair overlapping now, in world order. */
  def overlaps: IndexedSeq[(Shape, Shape)] = openPairs

  /** The shapes overlapping `sensor` now, in world order. */
  def visitors(sensor: Shape): IndexedSeq[Shape] = overlaps.collect { case (s, v) if s eq sensor => v }

  protected def makeBegin(k: Int): SensorBegin = SensorBegin(tracker.beginFirstShape(k), tracker.beginSecondShape(k))

  protected def makeEnd(k: Int): SensorEnd = SensorEnd(tracker.endFirstShape(k), tracker.endSecondShape(k))

  override def toString: String = s"SensorEvents($counts)"
