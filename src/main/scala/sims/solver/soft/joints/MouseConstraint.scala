package sims.solver.soft.joints

import sims.dynamics.joints.MouseJoint
import sims.solver.soft.{SoftContext, Softness}
import sims.solver.soft.SoftBodies.*

/** The mouse joint under the soft step: the soft point constraint of [[MouseJoint]],
  *   C = p - t (the grabbed point and the target),  Cdot = v + w x r,
  *   K = (1/m) E + 1/I [r.y^2, -r.x r.y; -r.x r.y, r.x^2],
  * with the soft step's own formulation of the spring (stiffness `frequency`, damping ratio
  * `dampingRatio`, which needs no scaling by the mass), in both passes of every substep:
  * lambda = -massScale K^-1 (Cdot + biasRate C) - impulseScale lambdaAcc; the accumulated impulse
  * (the force times one substep) stays within maxForce times the substep, and the body's rotation
  * is damped once per substep.
  */
private[sims] final class MouseConstraint(mouse: MouseJoint) extends JointConstraint(mouse, 2):
  private val point = mouse.attachment.arm()
  private val softness = Softness()
  private var index = 0
  private var startArmX, startArmY = 0.0
  private var maxImpulse = 0.0
  private var armX, armY = 0.0 // current, set by `measure`

  def prepare(context: SoftContext): Unit =
    index = mouse.node2.index
    point.update()
    startArmX = point.armX
    startArmY = point.armY
    softness.set(mouse.frequency, mouse.dampingRatio, context.h)
    // The accumulated impulse is re-applied in every substep (warm starting): it is the force
    // times one substep, bounded by maxForce times the substep.
    maxImpulse = mouse.maxForce * context.h
    clampImpulse()

  private def clampImpulse(): Unit =
    val size = math.sqrt(impulse(0) * impulse(0) + impulse(1) * impulse(1))
    if size > maxImpulse then
      impulse(0) *= maxImpulse / size
      impulse(1) *= maxImpulse / size

  private def measure(state: Array[Double]): Unit =
    val k = index * Stride
    armX = state(k + TurnCos) * startArmX - state(k + TurnSin) * startArmY
    armY = state(k + TurnSin) * startArmX + state(k + TurnCos) * startArmY

  def warmStart(context: SoftContext): Unit =
    val bodies = context.bodies
    if bodies.invMass(index) != 0 then
      measure(bodies.state)
      bodies.applyImpulse(index, impulse(0), impulse(1), armX, armY)

  def solve(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val m = bodies.invMass(index)
    if m != 0 then // a fixed body cannot be dragged
      val state = bodies.state
      val k = index * Stride
      if useBias then state(k + AngularVelocity) /= 1 + context.h * mouse.angularDamping
      measure(state)
      val i = bodies.invI(index)
      val target = mouse.target
      val cX = bodies.startX(index) + state(k + ShiftX) + armX - target.x
      val cY = bodies.startY(index) + state(k + ShiftY) + armY - target.y
      val rightX = state(k + VelocityX) - state(k + AngularVelocity) * armY + softness.biasRate * cX
      val rightY = state(k + VelocityY) + state(k + AngularVelocity) * armX + softness.biasRate * cY
      val k11 = m + i * armY * armY
      val k12 = -i * armX * armY
      val k22 = m + i * armX * armX
      val determinant = k11 * k22 - k12 * k12
      val oldX = impulse(0)
      val oldY = impulse(1)
      impulse(0) += -softness.massScale * (k22 * rightX - k12 * rightY) / determinant - softness.impulseScale * oldX
      impulse(1) += -softness.massScale * (k11 * rightY - k12 * rightX) / determinant - softness.impulseScale * oldY
      clampImpulse()
      bodies.applyImpulse(index, impulse(0) - oldX, impulse(1) - oldY, armX, armY)
