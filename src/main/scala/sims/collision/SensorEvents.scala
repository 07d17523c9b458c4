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
final class SensorEvents private[sims] (tracker: PairTracker):
  private val log = EventLog[SensorBegin, SensorEnd]()

  /** The shapes that began to overlap a sensor in the last step. */
  def begins: collection.IndexedSeq[SensorBegin] = log.shownBegins

  /** The shapes that stopped overlapping a sensor in the last step. */
  def ends: collection.IndexedSeq[SensorEnd] = log.shownEnds

  /** Every (sensor, visitor) pair overlapping now, in world order. */
  def overlaps: IndexedSeq[(Shape, Shape)] =
    tracker.openSorted().toIndexedSeq.map(i => (tracker.openFirstShape(i), tracker.openSecondShape(i)))

  /** The shapes overlapping `sensor` now, in world order. */
  def visitors(sensor: Shape): IndexedSeq[Shape] = overlaps.collect { case (s, v) if s eq sensor => v }

  /** Shows the tracker's events of the step just finished. */
  private[sims] def publish(): Unit =
    log.next()
    var k = 0
    while k < tracker.begins do
      log.nextBegins += SensorBegin(tracker.beginFirstShape(k), tracker.beginSecondShape(k))
      k += 1
    k = 0
    while k < tracker.ends do
      log.nextEnds += SensorEnd(tracker.endFirstShape(k), tracker.endSecondShape(k))
      k += 1
    log.show()

  /** The log of shown events (the world starts, undoes and clears it with the step). */
  private[sims] def shown: EventLog[SensorBegin, SensorEnd] = log

  override def toString: String = s"SensorEvents(${begins.size} begins, ${ends.size} ends)"
