package sims.solver.soft.joints

import sims.dynamics.joints.{JointLimits, JointMotor, JointSpring}
import sims.solver.soft.{SoftContext, Softness}

/** The one-dimensional rows every joint with a coordinate shares (an angle for a revolute
  * joint, a translation for a prismatic or wheel joint): a spring, a motor and the two ends of
  * a range, as Box2D v3 solves them. Each takes the row's effective mass m = 1 / (J M^-1 J^T),
  * its velocity Cdot = J v and what it accumulated so far, and returns the new accumulated
  * impulse; the caller applies the difference along J.
  */
private[sims] object AxisRows:
  /** A soft spring pulling the coordinate's error `c` to 0:
    * lambda += -massScale m (Cdot + biasRate c) - impulseScale lambda.
    */
  def spring(mass: Double, cdot: Double, c: Double, softness: Softness, accumulated: Double): Double =
    accumulated - softness.massScale * mass * (cdot + softness.biasRate * c) - softness.impulseScale * accumulated

  /** A motor driving Cdot to `speed` with an accumulated impulse of at most `maxImpulse` either
    * way: lambda = clamp(lambda - m (Cdot - speed)).
    */
  def motor(mass: Double, cdot: Double, speed: Double, maxImpulse: Double, accumulated: Double): Double =
    val next = accumulated - mass * (cdot - speed)
    math.max(-maxImpulse, math.min(maxImpulse, next))

  /** One end of a range, a one-sided row whose gap `c` must stay at least 0 (pushing only,
    * lambda >= 0): speculative while the gap is open (the bias c / h lets it close within the
    * substep and no further), soft with the joints' softness (solve pass) or rigid without bias
    * (relax pass) once it is closed.
    */
  def end(mass: Double, cdot: Double, c: Double, useBias: Boolean, inverseH: Double, jointSoftness: Softness,
      accumulated: Double): Double =
    var bias = 0.0
    var massScale = 1.0
    var impulseScale = 0.0
    if c > 0 then bias = c * inverseH
    else if useBias then
      bias = jointSoftness.biasRate * c
      massScale = jointSoftness.massScale
      impulseScale = jointSoftness.impulseScale
    val next = accumulated - massScale * mass * (cdot + bias) - impulseScale * accumulated
    math.max(next, 0.0)

  /** Sets `softness` to the joint's spring for a substep of h, if it has one (once a step). */
  def prepareSpring(spring: Option[JointSpring], softness: Softness, h: Double): Unit =
    spring match
      case Some(s) => softness.set(s.hertz, s.dampingRatio, h)
      case None =>

  /** The largest impulse the joint's motor may apply in a substep of h (0 without a motor). */
  def maxMotorImpulse(motor: Option[JointMotor], h: Double): Double =
    motor match
      case Some(m) => m.maxForce * h
      case None => 0.0

  /** The motor's row, if the joint has a motor: its accumulated impulse at `impulse(at)`, `apply`
    * and `cdot` as for `range`. Inline, as `range` is: no closure in the passes.
    */
  inline def drive(motor: Option[JointMotor], mass: Double, inline cdot: Double, maxImpulse: Double,
      impulse: Array[Double], at: Int, inline apply: Double => Unit): Unit =
    motor match
      case Some(m) =>
        val next = AxisRows.motor(mass, cdot, m.speed, maxImpulse, impulse(at))
        apply(next - impulse(at))
        impulse(at) = next
      case None =>

  /** Both ends of `range` on a coordinate at `c` with effective mass `mass`, their accumulated
    * impulses at `impulse(at)` (lower) and `impulse(at + 1)` (upper); `apply` applies a change of
    * impulse along the coordinate's Jacobian, and `cdot` (read again after the lower end's change)
    * is its velocity. Inline, with the caller's `apply` inlined too: no closure in the passes.
    */
  inline def range(range: JointLimits, mass: Double, inline cdot: Double, c: Double, useBias: Boolean,
      context: SoftContext, impulse: Array[Double], at: Int, inline apply: Double => Unit): Unit =
    val lower = end(mass, cdot, c - range.lower, useBias, context.inverseH, context.jointSoftness, impulse(at))
    apply(lower - impulse(at))
    impulse(at) = lower
    // The upper end's row is -c: its gap upper - c, its speed -Cdot, its impulse reversed.
    val upper = end(mass, -cdot, range.upper - c, useBias, context.inverseH, context.jointSoftness, impulse(at + 1))
    apply(impulse(at + 1) - upper)
    impulse(at + 1) = upper
