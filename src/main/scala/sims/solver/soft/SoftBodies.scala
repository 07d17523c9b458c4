package sims.solver.soft

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.Body

/** The bodies of a world during one soft step, in flat arrays indexed by `body.index`, so the
  * substeps' loops read and write contiguous doubles instead of chasing body objects.
  *
  * Positions are not moved during the substeps: each body keeps its placement at the start of
  * the step and accumulates its displacement (dx, dy) and turn (dAngle) since then, with the
  * turn's cosine and sine, from which contacts compute their current separation without a
  * narrowphase. `finish` writes the bodies back and places their shapes once.
  */
private[sims] final class SoftBodies:
  import SoftBodies.*

  /** Number of bodies. */
  var count: Int = 0
  /** The bodies, by index. */
  var bodies: Array[Body] = new Array[Body](0)
  /** Per body, `Stride` doubles: vx, vy, w, dx, dy, dAngle, cos(dAngle), sin(dAngle). */
  var state: Array[Double] = new Array[Double](0)
  /** Per body: 1 / mass and 1 / I (0 and 0 for a fixed body). */
  var invMass, invI: Array[Double] = new Array[Double](0)
  /** Per body: x, y and rotation at the start of the step. */
  var startX, startY, startAngle: Array[Double] = new Array[Double](0)
  /** Per body: the force and torque the user applied before the step. */
  var forceX, forceY, torque: Array[Double] = new Array[Double](0)
  /** Per body: the force and torque of the current substep (the user's plus the force joints'). */
  var substepForceX, substepForceY, substepTorque: Array[Double] = new Array[Double](0)

  /** Takes the state of the world's bodies at the start of a step. */
  def load(list: ArrayBuffer[Body]): Unit =
    count = list.length
    if bodies.length < count then grow(math.max(count, 2 * bodies.length))
    var i = 0
    while i < count do
      val b = list(i)
      bodies(i) = b
      val k = i * Stride
      state(k) = b.vx; state(k + 1) = b.vy; state(k + 2) = b.w
      state(k + 3) = 0; state(k + 4) = 0; state(k + 5) = 0
      state(k + 6) = 1; state(k + 7) = 0
      invMass(i) = b.invMass
      invI(i) = b.invI
      startX(i) = b.x; startY(i) = b.y; startAngle(i) = b.angle
      forceX(i) = b.fx; forceY(i) = b.fy; torque(i) = b.tau
      substepForceX(i) = b.fx; substepForceY(i) = b.fy; substepTorque(i) = b.tau
      i += 1

  /** Current x of body i's centre. */
  inline def x(i: Int): Double = startX(i) + state(i * Stride + 3)
  /** Current y of body i's centre. */
  inline def y(i: Int): Double = startY(i) + state(i * Stride + 4)
  /** Current rotation of body i. */
  inline def angle(i: Int): Double = startAngle(i) + state(i * Stride + 5)

  /** Adds the impulse (px, py) at arm (rx, ry) to body i's velocities. */
  inline def applyImpulse(i: Int, px: Double, py: Double, rx: Double, ry: Double): Unit =
    val k = i * Stride
    val m = invMass(i)
    state(k) += px * m
    state(k + 1) += py * m
    state(k + 2) += (rx * py - ry * px) * invI(i)

  /** Writes body i's current placement and velocities into the body object, without placing
    * its shapes (for joint code that reads bodies during the substeps).
    */
  def expose(i: Int): Unit =
    val b = bodies(i)
    val k = i * Stride
    b.x = startX(i) + state(k + 3)
    b.y = startY(i) + state(k + 4)
    b.angle = startAngle(i) + state(k + 5)
    b.vx = state(k); b.vy = state(k + 1); b.w = state(k + 2)

  /** Takes body i's velocities back from the body object (after joint code changed them). */
  def absorb(i: Int): Unit =
    val b = bodies(i)
    val k = i * Stride
    state(k) = b.vx; state(k + 1) = b.vy; state(k + 2) = b.w

  /** Ends the step: every body gets its new velocities and placement, its shapes are placed,
    * and forces are cleared.
    */
  def finish(): Unit =
    var i = 0
    while i < count do
      val b = bodies(i)
      val k = i * Stride
      b.vx = state(k); b.vy = state(k + 1); b.w = state(k + 2)
      b.x = startX(i) + state(k + 3)
      b.y = startY(i) + state(k + 4)
      b.angle = startAngle(i) + state(k + 5)
      b.fx = 0; b.fy = 0; b.tau = 0
      if state(k + 3) != 0 || state(k + 4) != 0 || state(k + 5) != 0 then b.placeShapes()
      i += 1

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

private[sims] object SoftBodies:
  /** Doubles per body in `state`. */
  inline val Stride = 8
