package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.collision.{ContactEvents, PairTracker, SensorEvents, SensorOverlaps}

/** A world's contact and sensor events: the pairs touching (overlapping) from step to step, the
  * events of the last step, and the sensor shapes (counted as they join, leave and change their
  * flag; listed in world order when the sensor stage next needs them).
  */
trait WorldEvents:
  this: World =>

  private[sims] val contactTracker = PairTracker(ordered = false)
  private[sims] val sensorTracker = PairTracker(ordered = true)
  private val contactLog = ContactEvents(contactTracker)
  private val sensorLog = SensorEvents(sensorTracker)
  private val sensorOverlaps = SensorOverlaps()
  private val sensorList = ArrayBuffer.empty[Shape]
  private var sensorCount = 0
  private var sensorListStale = false

  /** Whether the steps report contact events at all (default true). Off, a step spends no work
    * on them (the pairs touching end at the next step); sensor events are not affected.
    */
  var enableContactEvents: Boolean = true

  /** The contact events of the last step: the pairs of shapes that began to touch and those
    * that stopped, every begin followed by exactly one end in a later step (see
    * [[sims.collision.ContactEvents]]); valid until the next step.
    */
  def contactEvents: ContactEvents = contactLog

  /** The sensor events of the last step: the shapes that began and stopped overlapping a sensor
    * shape (`Shape.sensor`), paired like contact events (see [[sims.collision.SensorEvents]]).
    */
  def sensorEvents: SensorEvents = sensorLog

  /** Called by a shape of this world whose `sensor` flag changed to `value`. */
  private[sims] def sensorChanged(value: Boolean): Unit =
    sensorCount += (if value then 1 else -1)
    sensorListStale = true

  /** Counts the sensors of a body joining (`sign` 1) or leaving (-1). */
  protected def countSensors(body: Body, sign: Int): Unit =
    val sensors = body.shapes.count(_.sensor)
    if sensors > 0 then
      sensorCount += sign * sensors
      sensorListStale = true

  /** Starts the step's events: nothing touched yet. */
  protected def startEvents(): Unit =
    contactTracker.beginStep()
    sensorTracker.beginStep()

  /** The events of the step just solved: the pairs the solver found touching (a solver of the
    * library reports them as it goes; another one's are taken from its `contacts`), the sensors'
    * overlaps, then the begins and ends of both.
    */
  protected def finishEvents(): Unit =
    if !solver.reportsTouching && enableContactEvents then reportContacts()
    solver.finishContactEvents(this)
    if sensorCount > 0 then
      if sensorListStale then
        sensorList.clear()
        shapes.foreach(s => if s.sensor then sensorList += s)
        sensorListStale = false
      sensorOverlaps.find(this, sensorList, sensorTracker)
    sensorTracker.finishStep(this)

  /** Puts the open pairs back as they were before the failed step. */
  protected def undoEvents(): Unit =
    contactTracker.undoStep()
    sensorTracker.undoStep()

  /** The touching contacts of a solver that does not report them itself: every contact of its
    * `contacts` with a point at or below zero separation.
    */
  private def reportContacts(): Unit =
    for c <- solver.contacts(this) if c.touching do
      if contactTracker.touch(c.shape1, c.shape2) then
        val n = c.points.length
        contactTracker.describe(c.normal.x, c.normal.y, c.points.map(_.x).sum / n, c.points.map(_.y).sum / n, 0,
          c.normalImpulses.sum)

  /** Makes the pairs of a snapshot the open pairs of the contact and sensor events; the events
    * shown are forgotten.
    */
  private[sims] def restoreEvents(touching: PairTracker.Saved, overlapping: PairTracker.Saved): Unit =
    contactTracker.restoreOpen(touching)
    sensorTracker.restoreOpen(overlapping)
