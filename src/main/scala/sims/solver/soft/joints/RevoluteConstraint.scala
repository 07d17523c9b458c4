package sims.solver.soft.joints

import sims.dynamics.joints.RevoluteJoint
import sims.solver.soft.{SoftBodies, SoftContext, Softness}
import sims.solver.soft.SoftBodies.*

/** The revolute joint under the soft step: its pin ([[SoftPin]], impulses 0 and 1; in a joint
  * tree the direct solver's two rows), and, when the joint has them, the rows on the relative
  * turn theta = theta2 - theta1 - theta0 (Cdot = w2 - w1, effective mass 1 / (1/I1 + 1/I2)),
  * solved before the pin in every pass as Box2D v3 does: the spring (impulse 2), the motor
  * (impulse 3, at most maxForce h per substep) and the limits' lower and upper ends (impulses 4
  * and 5, one-sided; see [[AxisRows]]).
  */
private[sims] final class RevoluteConstraint(revolute: RevoluteJoint) extends JointConstraint(revolute, 6):
  private val pin = SoftPin(revolute.attachment1.arm(), revolute.attachment2.arm())
  private val springSoftness = Softness()
  // Set by `prepare`: whether the joint has turn rows this step, their effective mass, the
  // motor's largest impulse per substep.
  private var turning = false
  private var axialMass, maxMotorImpulse = 0.0

  def prepare(context: SoftContext): Unit =
    val bodies = context.bodies
    val i1 = revolute.node1.index
    val i2 = revolute.node2.index
    pin.prepare(bodies, i1, i2)
    turning = revolute.limits.nonEmpty || revolute.motor.nonEmpty || revolute.spring.nonEmpty
    // A part the joint no longer has carries no impulse into the step.
    if revolute.spring.isEmpty then impulse(2) = 0
    if revolute.motor.isEmpty then impulse(3) = 0
    if revolute.limits.isEmpty then { impulse(4) = 0; impulse(5) = 0 }
    if turning then
      val inverse = bodies.invI(i1) + bodies.invI(i2)
      axialMass = if inverse > 0 then 1 / inverse else 0
      AxisRows.prepareSpring(revolute.spring, springSoftness, context.h)
      maxMotorImpulse = AxisRows.maxMotorImpulse(revolute.motor, context.h)

  override def directRows: Int = 2

  override def rowsAt(context: SoftContext, rows: JointRows): Unit = pin.rowsAt(context, rows)

  def warmStart(context: SoftContext): Unit =
    if turning then turn(context.bodies, impulse(2) + impulse(3) + impulse(4) - impulse(5))
    pin.warmStart(context, impulse)

  def solve(context: SoftContext, useBias: Boolean): Unit =
    solveAxial(context, useBias)
    pin.solve(context, useBias, impulse)

  override def solvesAxial: Boolean = turning

  override def solveAxial(context: SoftContext, useBias: Boolean): Unit =
    if turning then
      val bodies = context.bodies
      val state = bodies.state
      val s1 = pin.index1 * Stride
      val s2 = pin.index2 * Stride
      def cdot = state(s2 + AngularVelocity) - state(s1 + AngularVelocity)
      def theta = bodies.angle(pin.index2) - bodies.angle(pin.index1) - revolute.referenceAngle
      if revolute.spring.nonEmpty then
        val next = AxisRows.spring(axialMass, cdot, theta, springSoftness, impulse(2))
        turn(bodies, next - impulse(2))
        impulse(2) = next
      AxisRows.drive(revolute.motor, axialMass, cdot, maxMotorImpulse, impulse, 3, turn(bodies, _))
      // A match rather than a closure: a closure here would be allocated in every pass.
      revolute.limits match
        case Some(range) => AxisRows.range(range, axialMass, cdot, theta, useBias, context, impulse, 4, turn(bodies, _))
        case None =>

  /** The turn impulse `lambda` on body 2, its opposite on body 1. */
  private def turn(bodies: SoftBodies, lambda: Double): Unit =
    val state = bodies.state
    state(pin.index1 * Stride + AngularVelocity) -= bodies.invI(pin.index1) * lambda
    state(pin.index2 * Stride + AngularVelocity) += bodies.invI(pin.index2) * lambda

  override def report(inverseH: Double): Unit =
    revolute.reactionX = impulse(0) * inverseH
    revolute.reactionY = impulse(1) * inverseH
    revolute.reactionTurn = (impulse(2) + impulse(3) + impulse(4) - impulse(5)) * inverseH
