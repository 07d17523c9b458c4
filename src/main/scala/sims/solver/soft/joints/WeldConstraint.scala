package sims.solver.soft.joints

import sims.dynamics.joints.WeldJoint
import sims.solver.soft.{SoftContext, Softness}
import sims.solver.soft.SoftBodies.*

/** The weld joint under the soft step, as Box2D v3 solves it: the relative turn
  * C = theta2 - theta1 - theta0 (Cdot = w2 - w1, mass 1 / (1/I1 + 1/I2); impulse 2) first, then
  * the pin ([[SoftPin]], impulses 0 and 1). Each is soft with the joints' stiffness in the solve
  * pass and rigid in the relax pass, or, given its own hertz, soft with that in both. A rigid
  * pin goes to the direct solver of joint trees (its two rows), the turn staying here.
  */
private[sims] final class WeldConstraint(weld: WeldJoint) extends JointConstraint(weld, 3):
  private val pin = SoftPin(weld.attachment1.arm(), weld.attachment2.arm())
  private val linearSoftness = Softness()
  private val angularSoftness = Softness()
  private var axialMass = 0.0

  def prepare(context: SoftContext): Unit =
    val bodies = context.bodies
    val i1 = weld.node1.index
    val i2 = weld.node2.index
    pin.prepare(bodies, i1, i2)
    val inverse = bodies.invI(i1) + bodies.invI(i2)
    axialMass = if inverse > 0 then 1 / inverse else 0
    if weld.linearHertz > 0 then linearSoftness.set(weld.linearHertz, weld.dampingRatio, context.h)
    if weld.angularHertz > 0 then angularSoftness.set(weld.angularHertz, weld.dampingRatio, context.h)

  override def directRows: Int = if weld.linearHertz > 0 then 0 else 2

  override def rowsAt(context: SoftContext, rows: JointRows): Unit = pin.rowsAt(context, rows)

  def warmStart(context: SoftContext): Unit =
    turn(context, impulse(2))
    pin.warmStart(context, impulse)

  def solve(context: SoftContext, useBias: Boolean): Unit =
    solveAxial(context, useBias)
    pin.solve(context, useBias, impulse, if weld.linearHertz > 0 then linearSoftness else null)

  override def solvesAxial: Boolean = true

  override def solveAxial(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val state = bodies.state
    val cdot = state(pin.index2 * Stride + AngularVelocity) - state(pin.index1 * Stride + AngularVelocity)
    var bias = 0.0
    var massScale = 1.0
    var impulseScale = 0.0
    if useBias || weld.angularHertz > 0 then
      val softness = if weld.angularHertz > 0 then angularSoftness else context.jointSoftness
      val c = bodies.angle(pin.index2) - bodies.angle(pin.index1) - weld.referenceAngle
      bias = softness.biasRate * c
      massScale = softness.massScale
      impulseScale = softness.impulseScale
    val lambda = -massScale * axialMass * (cdot + bias) - impulseScale * impulse(2)
    impulse(2) += lambda
    turn(context, lambda)

  /** The turn impulse `lambda` on body 2, its opposite on body 1. */
  private def turn(context: SoftContext, lambda: Double): Unit =
    val bodies = context.bodies
    val state = bodies.state
    state(pin.index1 * Stride + AngularVelocity) -= bodies.invI(pin.index1) * lambda
    state(pin.index2 * Stride + AngularVelocity) += bodies.invI(pin.index2) * lambda

  override def report(inverseH: Double): Unit =
    weld.reactionX = impulse(0) * inverseH
    weld.reactionY = impulse(1) * inverseH
    weld.reactionTurn = impulse(2) * inverseH
