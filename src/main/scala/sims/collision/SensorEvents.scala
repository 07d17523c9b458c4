package sims.collision

import scala.collection.mutable.ArrayBuffer
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
  // The events as objects, made from the tracker's arrays when first asked for after a step.
  private val beginList = ArrayBuffer.empty[SensorBegin]
  private val endList = ArrayBuffer.empty[SensorEnd]
  private var made = -1L

  /** The shapes that began to overlap a sensor in the last step. */
  def begins: collection.IndexedSeq[SensorBegin] =
    make()
    beginList

  /** The shapes that stopped overlapping a sensor in the last step. */
  def ends: collection.IndexedSeq[SensorEnd] =
    make()
    endList

  /** Every (sensor, visitor) pair overlapping now, in world order. */
  def overlaps: IndexedSeq[(Shape, Shape)] =
    val pairs = tracker.openPairs()
    IndexedSeq.tabulate(pairs.keys.length)(i => (pairs.first(i), pairs.second(i)))

  /** The shapes overlapping `sensor` now, in world order. */
  def visitors(sensor: Shape): IndexedSeq[Shape] = overlaps.collect { case (s, v) if s eq sensor => v }

  /** Makes the event objects of the last step, unless made already. */
  private def make(): Unit =
    if made != tracker.generation then
      beginList.clear()
      endList.clear()
      var k = 0
      while k < tracker.begins do
        beginList += SensorBegin(tracker.beginFirstShape(k), tracker.beginSecondShape(k))
        k += 1
      k = 0
      while k < tracker.ends do
        endList += SensorEnd(tracker.endFirstShape(k), tracker.endSecondShape(k))
        k += 1
      made = tracker.generation

  override def toString: String = s"SensorEvents(${tracker.begins} begins, ${tracker.ends} ends)"
