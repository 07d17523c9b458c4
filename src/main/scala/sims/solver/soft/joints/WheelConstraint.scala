package sims.solver.soft.joints

import sims.geometry.PortableMath
import sims.dynamics.joints.WheelJoint
import sims.solver.soft.{SoftBodies, SoftContext, Softness}
import sims.solver.soft.SoftBodies.*

/** The wheel joint under the soft step, in Box2D v3's order within each pass: the motor on the
  * relative turn w2 - w1 (impulse 2, at most maxForce h per substep), the suspension spring
  * along the axis u (impulse 1), the limits' ends along u (impulses 3 and 4; see [[AxisRows]]),
  * then the line C = n . d (impulse 0, soft with the joints' stiffness, rigid in the relax
  * pass). Along a direction a (u or n): Cdot = a . (v2 - v1) + (r2 x a) w2 - ((d + r1) x a) w1.
  */
private[sims] final class WheelConstraint(wheel: WheelJoint) extends JointConstraint(wheel, 5):
  private val point1 = wheel.attachment1.arm()
  private val point2 = wheel.attachment2.arm()
  private val ends = SoftAnchors()
  private val springSoftness = Softness()
  private var startAxisX, startAxisY = 0.0
  private var maxMotorImpulse, turnMass = 0.0
  // Set by `measure`: the axis, d's parts along it and n, and the angular terms along each.
  private var axisX, axisY, along, across, slide1, slide2, side1, side2 = 0.0

  def prepare(context: SoftContext): Unit =
    point1.update()
    point2.update()
    val angle = wheel.node1.angle
    val c = PortableMath.cos(angle)
    val s = PortableMath.sin(angle)
    startAxisX = wheel.localAxisX * c - wheel.localAxisY * s
    startAxisY = wheel.localAxisX * s + wheel.localAxisY * c
    val bodies = context.bodies
    val i1 = wheel.node1.index
    val i2 = wheel.node2.index
    ends.start(bodies, i1, i2, point1.armX, point1.armY, point2.armX, point2.armY)
    if wheel.spring.isEmpty then impulse(1) = 0
    if wheel.motor.isEmpty then impulse(2) = 0
    if wheel.limits.isEmpty then { impulse(3) = 0; impulse(4) = 0 }
    AxisRows.prepareSpring(wheel.spring, springSoftness, context.h)
    maxMotorImpulse = AxisRows.maxMotorImpulse(wheel.motor, context.h)
    val inverse = bodies.invI(i1) + bodies.invI(i2)
    turnMass = if inverse > 0 then 1 / inverse else 0

  private def measure(state: Array[Double]): Unit =
    ends.measure(state)
    val s1 = ends.index1 * Stride
    val c1 = state(s1 + TurnCos); val sn1 = state(s1 + TurnSin)
    axisX = c1 * startAxisX - sn1 * startAxisY
    axisY = sn1 * startAxisX + c1 * startAxisY
    // n = u.leftNormal = (-u.y, u.x)
    val normalX = -axisY
    val normalY = axisX
    val reachX = ends.centresX + ends.arm2X // d + r1 = p2 - x1
    val reachY = ends.centresY + ends.arm2Y
    val dx = reachX - ends.arm1X
    val dy = reachY - ends.arm1Y
    along = axisX * dx + axisY * dy
    across = normalX * dx + normalY * dy
    slide1 = reachX * axisY - reachY * axisX
    slide2 = ends.arm2X * axisY - ends.arm2Y * axisX
    side1 = reachX * normalY - reachY * normalX
    side2 = ends.arm2X * normalY - ends.arm2Y * normalX

  /** The impulse lambda along (ax, ay) with angular terms a1, a2: on body 2, its opposite on body 1. */
  private def push(bodies: SoftBodies, ax: Double, ay: Double, a1: Double, a2: Double, lambda: Double): Unit =
    val state = bodies.state
    val i1 = ends.index1
    val i2 = ends.index2
    val s1 = i1 * Stride
    val s2 = i2 * Stride
    state(s1 + VelocityX) -= ax * lambda * bodies.invMass(i1)
    state(s1 + VelocityY) -= ay * lambda * bodies.invMass(i1)
    state(s1 + AngularVelocity) -= a1 * lambda * bodies.invI(i1)
    state(s2 + VelocityX) += ax * lambda * bodies.invMass(i2)
    state(s2 + VelocityY) += ay * lambda * bodies.invMass(i2)
    state(s2 + AngularVelocity) += a2 * lambda * bodies.invI(i2)

  private def speed(state: Array[Double], ax: Double, ay: Double, a1: Double, a2: Double): Double =
    val s1 = ends.index1 * Stride
    val s2 = ends.index2 * Stride
    ax * (state(s2 + VelocityX) - state(s1 + VelocityX)) + ay * (state(s2 + VelocityY) - state(s1 + VelocityY)) +
      a2 * state(s2 + AngularVelocity) - a1 * state(s1 + AngularVelocity)

  private def mass(bodies: SoftBodies, a1: Double, a2: Double): Double =
    val i1 = ends.index1
    val i2 = ends.index2
    val k = bodies.invMass(i1) + bodies.invMass(i2) + bodies.invI(i1) * a1 * a1 + bodies.invI(i2) * a2 * a2
    if k > 0 then 1 / k else 0.0

  def warmStart(context: SoftContext): Unit =
    val bodies = context.bodies
    measure(bodies.state)
    push(bodies, -axisY, axisX, side1, side2, impulse(0))
    push(bodies, axisX, axisY, slide1, slide2, impulse(1) + impulse(3) - impulse(4))
    turn(bodies, impulse(2))

  def solve(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val state = bodies.state
    measure(state)
    val s1 = ends.index1 * Stride
    val s2 = ends.index2 * Stride
    AxisRows.drive(wheel.motor, turnMass, state(s2 + AngularVelocity) - state(s1 + AngularVelocity), maxMotorImpulse,
      impulse, 2, turn(bodies, _))
    val axial = mass(bodies, slide1, slide2)
    if wheel.spring.nonEmpty then
      val next = AxisRows.spring(axial, speed(state, axisX, axisY, slide1, slide2), along, springSoftness, impulse(1))
      push(bodies, axisX, axisY, slide1, slide2, next - impulse(1))
      impulse(1) = next
    wheel.limits match
      case Some(range) =>
        AxisRows.range(range, axial, speed(state, axisX, axisY, slide1, slide2), along, useBias, context, impulse, 3,
          push(bodies, axisX, axisY, slide1, slide2, _))
      case None =>
    // The line, soft in the solve pass, rigid in the relax pass.
    var bias = 0.0
    var massScale = 1.0
    var impulseScale = 0.0
    if useBias then
      val softness = context.jointSoftness
      bias = softness.biasRate * across
      massScale = softness.massScale
      impulseScale = softness.impulseScale
    val cdot = speed(state, -axisY, axisX, side1, side2)
    val lambda = -massScale * mass(bodies, side1, side2) * (cdot + bias) - impulseScale * impulse(0)
    impulse(0) += lambda
    push(bodies, -axisY, axisX, side1, side2, lambda)

  /** The turn impulse `lambda` on body 2, its opposite on body 1. */
  private def turn(bodies: SoftBodies, lambda: Double): Unit =
    val state = bodies.state
    state(ends.index1 * Stride + AngularVelocity) -= bodies.invI(ends.index1) * lambda
    state(ends.index2 * Stride + AngularVelocity) += bodies.invI(ends.index2) * lambda

  override def report(inverseH: Double): Unit =
    val alongImpulse = impulse(1) + impulse(3) - impulse(4)
    wheel.reactionX = (-axisY * impulse(0) + axisX * alongImpulse) * inverseH
    wheel.reactionY = (axisX * impulse(0) + axisY * alongImpulse) * inverseH
    wheel.reactionTurn = impulse(2) * inverseH
