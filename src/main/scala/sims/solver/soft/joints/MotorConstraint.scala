package sims.solver.soft.joints

import sims.geometry.PortableMath
import sims.dynamics.joints.MotorJoint
import sims.solver.soft.SoftContext
import sims.solver.soft.SoftBodies.*

/** The motor joint under the soft step (see [[MotorJoint]] for its rows): the turn (impulse 2)
  * then the point (impulses 0 and 1), each clamped to what its maximum allows per substep, in
  * both passes (its bias is the joint's own correction, not the soft step's stiffness).
  */
private[sims] final class MotorConstraint(motor: MotorJoint) extends JointConstraint(motor, 3):
  private var index1, index2 = 0
  private var offsetX, offsetY, maxImpulse, maxAngularImpulse, turnMass = 0.0

  def prepare(context: SoftContext): Unit =
    val bodies = context.bodies
    index1 = motor.node1.index
    index2 = motor.node2.index
    val target = motor.targetOffset
    offsetX = target.x
    offsetY = target.y
    maxImpulse = motor.maxForce * context.h
    maxAngularImpulse = motor.maxTorque * context.h
    val inverse = bodies.invI(index1) + bodies.invI(index2)
    turnMass = if inverse > 0 then 1 / inverse else 0

  def warmStart(context: SoftContext): Unit =
    val bodies = context.bodies
    measureArm(bodies)
    bodies.applyImpulse(index1, -impulse(0), -impulse(1), armX, armY)
    bodies.applyImpulse(index2, impulse(0), impulse(1), 0, 0)
    turn(context, impulse(2))

  // From body 1's centre to body 2's, set by `measureArm`.
  private var armX, armY = 0.0

  private def measureArm(bodies: sims.solver.soft.SoftBodies): Unit =
    armX = bodies.x(index2) - bodies.x(index1)
    armY = bodies.y(index2) - bodies.y(index1)

  def solve(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val state = bodies.state
    val s1 = index1 * Stride
    val s2 = index2 * Stride
    val factor = motor.correctionFactor * context.inverseH
    // The turn.
    val angleGap = bodies.angle(index2) - bodies.angle(index1) - motor.targetAngle
    val cdot = state(s2 + AngularVelocity) - state(s1 + AngularVelocity)
    val nextTurn = math.max(-maxAngularImpulse,
      math.min(maxAngularImpulse, impulse(2) - turnMass * (cdot + factor * angleGap)))
    turn(context, nextTurn - impulse(2))
    impulse(2) = nextTurn
    // The point: C = x2 - x1 - R1 offset.
    measureArm(bodies)
    val angle1 = bodies.angle(index1)
    val c = PortableMath.cos(angle1)
    val s = PortableMath.sin(angle1)
    val gapX = armX - (c * offsetX - s * offsetY)
    val gapY = armY - (s * offsetX + c * offsetY)
    val w1 = state(s1 + AngularVelocity)
    val speedX = state(s2 + VelocityX) - state(s1 + VelocityX) + w1 * armY + factor * gapX
    val speedY = state(s2 + VelocityY) - state(s1 + VelocityY) - w1 * armX + factor * gapY
    // K = (m1 + m2) E + i1 [ay^2, -ax ay; -ax ay, ax^2] (the arm on body 1 only).
    val m = bodies.invMass(index1) + bodies.invMass(index2)
    val i1 = bodies.invI(index1)
    val k11 = m + i1 * armY * armY
    val k12 = -i1 * armX * armY
    val k22 = m + i1 * armX * armX
    val determinant = k11 * k22 - k12 * k12
    if determinant > 0 then
      val px = -(k22 * speedX - k12 * speedY) / determinant
      val py = -(k11 * speedY - k12 * speedX) / determinant
      var nextX = impulse(0) + px
      var nextY = impulse(1) + py
      val length = math.sqrt(nextX * nextX + nextY * nextY)
      if length > maxImpulse then
        nextX *= maxImpulse / length
        nextY *= maxImpulse / length
      val dx = nextX - impulse(0)
      val dy = nextY - impulse(1)
      impulse(0) = nextX
      impulse(1) = nextY
      bodies.applyImpulse(index1, -dx, -dy, armX, armY)
      bodies.applyImpulse(index2, dx, dy, 0, 0)

  /** The turn impulse `lambda` on body 2, its opposite on body 1. */
  private def turn(context: SoftContext, lambda: Double): Unit =
    val bodies = context.bodies
    val state = bodies.state
    state(index1 * Stride + AngularVelocity) -= bodies.invI(index1) * lambda
    state(index2 * Stride + AngularVelocity) += bodies.invI(index2) * lambda

  override def report(inverseH: Double): Unit =
    motor.reactionX = impulse(0) * inverseH
    motor.reactionY = impulse(1) * inverseH
    motor.reactionTurn = impulse(2) * inverseH
