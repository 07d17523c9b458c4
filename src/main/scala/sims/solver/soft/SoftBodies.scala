package sims.solver.soft

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.{Body, WorldState}

/** The bodies of a world during one soft step, in flat arrays indexed by `body.index`, so the
  * substeps' loops read and write contiguous doubles instead of chasing body objects.
  *
  * Positions are not moved during the substeps: each body keeps its placement at the start of
  * the step and accumulates its displacement (dx, dy) and turn (dAngle) since then, with the
  * turn's cosine and sine, from which contacts compute their current separation without a
  * narrowphase. `finishRange` writes the bodies back and places their shapes once.
  */
private[sims] final class SoftBodies:
  import SoftBodies.*

  /** Number of bodies. */
  var count: Int = 0
  /** The bodies, by index. */
  var bodies: Array[Body] = new Array[Body](0)
  /** Per body, `Stride` doubles at the offsets named in the companion: velocities, the
    * displacement and turn since the step began, the turn's cosine and sine.
    */
  var state: Array[Double] = new Array[Double](0)
  /** Per body: 1 / mass and 1 / I (0 and 0 for a fixed body). */
  var invMass, invI: Array[Double] = new Array[Double](0)
  /** Per body: x, y and rotation at the start of the step. */
  var startX, startY, startAngle: Array[Double] = new Array[Double](0)
  /** Per body: the force and torque the user applied before the step. */
  var forceX, forceY, torque: Array[Double] = new Array[Double](0)
  /** Per body: the force and torque of the current substep (the user's plus the force joints'). */
  var substepForceX, substepForceY, substepTorque: Array[Double] = new Array[Double](0)
  /** Per body: asleep (not moved by this step: its inverse masses are 0 here, as a fixed body's). */
  var asleep: Array[Boolean] = new Array[Boolean](0)
  /** Whether any body is asleep. */
  var anyAsleep: Boolean = false

  /** Per body: the part of gravity acting on it, and the factors its velocities are multiplied
    * by in each substep (1 / (1 + h damping); 1 without damping).
    */
  var gravityScale, linearDecay, angularDecay: Array[Double] = new Array[Double](0)
  /** Whether some body has a damping (the substeps then apply the decays). */
  var anyDamped: Boolean = false

  /** Makes room for the bodies of `list`, whose state at the start of a step `loadRange` takes
    * (in one range or several) and `loaded` ends.
    */
  def begin(list: ArrayBuffer[Body]): Unit =
    count = list.length
    if bodies.length < count then grow(math.max(count, 2 * bodies.length))

  /** Takes the state of bodies `from` until `until` of `list`, and saves it into `saved` (the
    * world's state before the step: one read of each body for both); returns `Asleep` if one of
    * them sleeps, plus `Damped` if one has a damping. Writes those bodies' slots only: ranges may
    * be taken on several threads at once.
    */
  def loadRange(list: ArrayBuffer[Body], saved: WorldState, h: Double, from: Int, until: Int): Int =
    var flags = 0
    var i = from
    while i < until do
      val b = list(i)
      saved.saveBody(i, b)
      if bodies(i) ne b then bodies(i) = b // no write barrier for the same body as last step
      gravityScale(i) = b.gravityScale
      if b.damped then
        flags |= Damped
        linearDecay(i) = 1 / (1 + h * b.linearDamping)
        angularDecay(i) = 1 / (1 + h * b.angularDamping)
      else
        linearDecay(i) = 1
        angularDecay(i) = 1
      val k = i * Stride
      state(k + VelocityX) = b.vx; state(k + VelocityY) = b.vy; state(k + AngularVelocity) = b.w
      state(k + ShiftX) = 0; state(k + ShiftY) = 0; state(k + Turn) = 0
      state(k + TurnCos) = 1; state(k + TurnSin) = 0
      val sleeping = !b.isAwake
      asleep(i) = sleeping
      if sleeping then flags |= Asleep
      invMass(i) = if sleeping then 0 else b.invMass
      invI(i) = if sleeping then 0 else b.invI
      startX(i) = b.x; startY(i) = b.y; startAngle(i) = b.angle
      forceX(i) = b.fx; forceY(i) = b.fy; torque(i) = b.tau
      substepForceX(i) = b.fx; substepForceY(i) = b.fy; substepTorque(i) = b.tau
      i += 1
    flags

  /** Ends the loading: `flags`, every range's of `loadRange` or-ed together. */
  def loaded(flags: Int): Unit =
    anyAsleep = (flags & Asleep) != 0
    anyDamped = (flags & Damped) != 0

  /** Wakes every body asleep in `island`: it takes part in the step from now on. */
  def wakeIsland(island: Long): Unit =
    var i = 0
    while i < count do
      val b = bodies(i)
      if asleep(i) && b.sleepIsland == island then
        b.wakeAlone()
        asleep(i) = false
        invMass(i) = b.invMass
        invI(i) = b.invI
      i += 1

  /** Current x of body i's centre. */
  inline def x(i: Int): Double = startX(i) + state(i * Stride + ShiftX)
  /** Current y of body i's centre. */
  inline def y(i: Int): Double = startY(i) + state(i * Stride + ShiftY)
  /** Current rotation of body i. */
  inline def angle(i: Int): Double = startAngle(i) + state(i * Stride + Turn)

  /** Whether the substep forces and the velocities of bodies `from` until `until` are all
    * finite. One sum per range: finite values sum to a finite value or overflow to an infinity,
    * so a false answer only sends the caller to the exact checks.
    */
  def finiteMotion(from: Int, until: Int): Boolean =
    var sum = 0.0
    var i = from
    while i < until do
      val k = i * Stride
      sum += (substepForceX(i) + substepForceY(i) + substepTorque(i)) +
        (state(k + VelocityX) + state(k + VelocityY) + state(k + AngularVelocity))
      i += 1
    finite(sum)

  /** The first body whose velocities are not all finite, or -1. */
  def firstNonFiniteVelocity(): Int =
    var i = 0
    while i < count && finite(state(i * Stride + VelocityX)) && finite(state(i * Stride + VelocityY)) &&
      finite(state(i * Stride + AngularVelocity)) do i += 1
    if i < count then i else -1

  /** Adds the impulse (px, py) at arm (rx, ry) to body i's velocities. */
  inline def applyImpulse(i: Int, px: Double, py: Double, rx: Double, ry: Double): Unit =
    val k = i * Stride
    val m = invMass(i)
    state(k + VelocityX) += px * m
    state(k + VelocityY) += py * m
    state(k + AngularVelocity) += (rx * py - ry * px) * invI(i)

  /** Writes body i's current placement and velocities into the body object, without placing
    * its shapes (for joint code that reads bodies during the substeps).
    */
  def expose(i: Int): Unit =
    val b = bodies(i)
    val k = i * Stride
    b.x = startX(i) + state(k + ShiftX)
    b.y = startY(i) + state(k + ShiftY)
    b.angle = startAngle(i) + state(k + Turn)
    b.vx = state(k + VelocityX); b.vy = state(k + VelocityY); b.w = state(k + AngularVelocity)

  /** Takes body i's velocities back from the body object (after joint code changed them). */
  def absorb(i: Int): Unit =
    val b = bodies(i)
    val k = i * Stride
    state(k + VelocityX) = b.vx; state(k + VelocityY) = b.vy; state(k + AngularVelocity) = b.w

  /** Ends the step for bodies `from` until `until`: each gets its new velocities and placement,
    * its shapes are placed (and their bounds computed, see `Shape.refreshBounds`), its forces
    * cleared. Returns whether their velocities and placements are all finite. Writes those
    * bodies and their shapes only: ranges may be finished on several threads at once.
    */
  def finishRange(from: Int, until: Int): Boolean =
    var sum = 0.0
    var i = from
    while i < until do
      val b = bodies(i)
      val k = i * Stride
      b.vx = state(k + VelocityX); b.vy = state(k + VelocityY); b.w = state(k + AngularVelocity)
      b.x = startX(i) + state(k + ShiftX)
      b.y = startY(i) + state(k + ShiftY)
      b.angle = startAngle(i) + state(k + Turn)
      b.fx = 0; b.fy = 0; b.tau = 0
      if state(k + ShiftX) != 0 || state(k + ShiftY) != 0 || state(k + Turn) != 0 then
        b.placeShapes()
        b.refreshShapeBounds()
      // Finite values sum to a finite value or overflow to an infinity (then the guard looks
      // closer, and finds every value finite): one test for the range.
      sum += (b.vx + b.vy + b.w) + (b.x + b.y + b.angle)
      i += 1
    finite(sum)

  // java.lang.Double.isFinite is static: `d.isNaN` goes through a boxed java.lang.Double.
  private inline def finite(d: Double): Boolean = java.lang.Double.isFinite(d)

  private def grow(capacity: Int): Unit =
    bodies = new Array[Body](capacity)
    state = new Array[Double](capacity * Stride)
    invMass = new Array[Double](capacity); invI = new Array[Double](capacity)
    startX = new Array[Double](capacity); startY = new Array[Double](capacity)
    startAngle = new Array[Double](capacity)
    forceX = new Array[Double](capacity); forceY = new Array[Double](capacity)
    torque = new Array[Double](capacity)
    substepForceX = new Array[Double](capacity); substepForceY = new Array[Double](capacity)
    substepTorque = new Array[Double](capacity)
    asleep = new Array[Boolean](capacity)
    gravityScale = new Array[Double](capacity)
    linearDecay = new Array[Double](capacity); angularDecay = new Array[Double](capacity)

/** The layout of `SoftBodies.state`: body i's values start at `i * Stride`, at these offsets.
  * This is the one place that names them; every reader and writer uses the names.
  */
private[sims] object SoftBodies:
  /** Linear velocity, x and y, m/s. */
  inline val VelocityX = 0
  inline val VelocityY = 1
  /** Angular velocity, rad/s. */
  inline val AngularVelocity = 2
  /** Displacement of the centre since the step began, x and y, m. */
  inline val ShiftX = 3
  inline val ShiftY = 4
  /** Turn since the step began, rad, with its cosine and sine (integrated as a unit complex number). */
  inline val Turn = 5
  inline val TurnCos = 6
  inline val TurnSin = 7
  /** Doubles per body in `state`. */
  inline val Stride = 8

  /** `loadRange`'s flags: a body of the range sleeps; a body of the range has a damping. */
  inline val Asleep = 1
  inline val Damped = 2
