package sims.solver.soft.joints

import sims.dynamics.joints.{PrismaticJoint, PrismaticMatrix}
import sims.geometry.PortableMath
import sims.solver.soft.{SoftBodies, SoftContext, Softness}
import sims.solver.soft.SoftBodies.*

/** The prismatic joint under the soft step: the two rows of [[PrismaticJoint]],
  *   C = (n . d, theta2 - theta1 - theta0),
  *   Cdot = (n . (v2 - v1) + a2 w2 - a1 w1, w2 - w1),  a1 = (d + r1) x n, a2 = r2 x n,
  * with K at the current geometry (the arms and n at the start of the step turned by the bodies'
  * rotations since), solved as a soft constraint: lambda = -massScale K^-1 (Cdot + biasRate C)
  * - impulseScale lambdaAcc (relax pass: the rigid lambda = -K^-1 Cdot).
  * When the joint has them, the rows along the line come first in every pass, as in Box2D v3:
  * with u the line's direction, the translation s = u . d, Cdot = u . (v2 - v1) + b2 w2 - b1 w1,
  * b1 = (d + r1) x u, b2 = r2 x u: the spring (impulse 2), the motor (impulse 3, at most
  * maxForce h per substep) and the limits' ends (impulses 4 and 5; see [[AxisRows]]).
  */
private[sims] final class PrismaticConstraint(prismatic: PrismaticJoint) extends JointConstraint(prismatic, 6):
  private val point1 = prismatic.attachment1.arm()
  private val point2 = prismatic.attachment2.arm()
  private val ends = SoftAnchors()
  private val matrix = PrismaticMatrix()
  private var startNormalX, startNormalY = 0.0
  // The current geometry, set by `measure`: the normal, the angular terms and the line error.
  private var normalX, normalY, angular1, angular2, lineError = 0.0
  // The rows along the line: whether there are any this step, the spring's softness, the
  // motor's largest impulse per substep; set by `measureAxis`: the translation, b1 and b2.
  private var sliding = false
  private val springSoftness = Softness()
  private var maxMotorImpulse, translation, slide1, slide2 = 0.0

  def prepare(context: SoftContext): Unit =
    point1.update()
    point2.update()
    // n = u.leftNormal, u = the line's direction turned by body 1's rotation.
    val angle = prismatic.node1.angle
    val c = PortableMath.cos(angle)
    val s = PortableMath.sin(angle)
    startNormalX = -(prismatic.localAxisX * s + prismatic.localAxisY * c)
    startNormalY = prismatic.localAxisX * c - prismatic.localAxisY * s
    ends.start(context.bodies, prismatic.node1.index, prismatic.node2.index, point1.armX, point1.armY, point2.armX,
      point2.armY)
    sliding = prismatic.limits.nonEmpty || prismatic.motor.nonEmpty || prismatic.spring.nonEmpty
    // A part the joint no longer has carries no impulse into the step.
    if prismatic.spring.isEmpty then impulse(2) = 0
    if prismatic.motor.isEmpty then impulse(3) = 0
    if prismatic.limits.isEmpty then { impulse(4) = 0; impulse(5) = 0 }
    AxisRows.prepareSpring(prismatic.spring, springSoftness, context.h)
    maxMotorImpulse = AxisRows.maxMotorImpulse(prismatic.motor, context.h)

  /** Sets n, a1, a2 and the line error from the bodies' motion since the step began. */
  private def measure(state: Array[Double]): Unit =
    ends.measure(state)
    // The normal turns with body 1.
    val s1 = ends.index1 * Stride
    val c1 = state(s1 + TurnCos); val sn1 = state(s1 + TurnSin)
    normalX = c1 * startNormalX - sn1 * startNormalY
    normalY = sn1 * startNormalX + c1 * startNormalY
    // d + r1 = p2 - x1
    val reachX = ends.centresX + ends.arm2X
    val reachY = ends.centresY + ends.arm2Y
    angular1 = reachX * normalY - reachY * normalX
    angular2 = ends.arm2X * normalY - ends.arm2Y * normalX
    lineError = normalX * (reachX - ends.arm1X) + normalY * (reachY - ends.arm1Y)

  /** The relative rotation's error: theta2 - theta1 - theta0. */
  private def angleError(bodies: SoftBodies): Double =
    bodies.angle(ends.index2) - bodies.angle(ends.index1) - prismatic.referenceAngle

  /** Applies the line impulse `line` and the turn impulse `turn` to both bodies. */
  private def apply(bodies: SoftBodies, line: Double, turn: Double): Unit =
    val state = bodies.state
    val index1 = ends.index1
    val index2 = ends.index2
    val s1 = index1 * Stride
    val s2 = index2 * Stride
    val px = normalX * line
    val py = normalY * line
    state(s1 + VelocityX) -= px * bodies.invMass(index1)
    state(s1 + VelocityY) -= py * bodies.invMass(index1)
    state(s1 + AngularVelocity) -= (angular1 * line + turn) * bodies.invI(index1)
    state(s2 + VelocityX) += px * bodies.invMass(index2)
    state(s2 + VelocityY) += py * bodies.invMass(index2)
    state(s2 + AngularVelocity) += (angular2 * line + turn) * bodies.invI(index2)

  /** Sets the translation and the line rows' angular terms b1, b2 (after `measure`). */
  private def measureAxis(): Unit =
    // u = (n.y, -n.x): n is u's left normal.
    val axisX = normalY
    val axisY = -normalX
    val reachX = ends.centresX + ends.arm2X
    val reachY = ends.centresY + ends.arm2Y
    translation = axisX * (reachX - ends.arm1X) + axisY * (reachY - ends.arm1Y)
    slide1 = reachX * axisY - reachY * axisX
    slide2 = ends.arm2X * axisY - ends.arm2Y * axisX

  /** Applies the impulse `lambda` along the line (u lambda on body 2, its opposite on body 1). */
  private def slide(bodies: SoftBodies, lambda: Double): Unit =
    val state = bodies.state
    val index1 = ends.index1
    val index2 = ends.index2
    val s1 = index1 * Stride
    val s2 = index2 * Stride
    val px = normalY * lambda
    val py = -normalX * lambda
    state(s1 + VelocityX) -= px * bodies.invMass(index1)
    state(s1 + VelocityY) -= py * bodies.invMass(index1)
    state(s1 + AngularVelocity) -= slide1 * lambda * bodies.invI(index1)
    state(s2 + VelocityX) += px * bodies.invMass(index2)
    state(s2 + VelocityY) += py * bodies.invMass(index2)
    state(s2 + AngularVelocity) += slide2 * lambda * bodies.invI(index2)

  override def solvesAxial: Boolean = sliding

  override def solveAxial(context: SoftContext, useBias: Boolean): Unit =
    if sliding then
      val bodies = context.bodies
      val state = bodies.state
      measure(state)
      measureAxis()
      val index1 = ends.index1
      val index2 = ends.index2
      val s1 = index1 * Stride
      val s2 = index2 * Stride
      val k = bodies.invMass(index1) + bodies.invMass(index2) + bodies.invI(index1) * slide1 * slide1 +
        bodies.invI(index2) * slide2 * slide2
      val mass = if k > 0 then 1 / k else 0.0
      def cdot = normalY * (state(s2 + VelocityX) - state(s1 + VelocityX)) -
        normalX * (state(s2 + VelocityY) - state(s1 + VelocityY)) +
        slide2 * state(s2 + AngularVelocity) - slide1 * state(s1 + AngularVelocity)
      if prismatic.spring.nonEmpty then
        val next = AxisRows.spring(mass, cdot, translation - prismatic.initialTranslation, springSoftness,
          impulse(2))
        slide(bodies, next - impulse(2))
        impulse(2) = next
      AxisRows.drive(prismatic.motor, mass, cdot, maxMotorImpulse, impulse, 3, slide(bodies, _))
      // A match rather than a closure: a closure here would be allocated in every pass.
      prismatic.limits match
        case Some(range) =>
          AxisRows.range(range, mass, cdot, translation, useBias, context, impulse, 4, slide(bodies, _))
        case None =>

  override def report(inverseH: Double): Unit =
    val along = impulse(2) + impulse(3) + impulse(4) - impulse(5)
    // n lambda_line + u lambda_along, with u = (n.y, -n.x).
    prismatic.reactionX = (normalX * impulse(0) + normalY * along) * inverseH
    prismatic.reactionY = (normalY * impulse(0) - normalX * along) * inverseH
    prismatic.reactionTurn = impulse(1) * inverseH

  override def directRows: Int = 2

  override def rowsAt(context: SoftContext, rows: JointRows): Unit =
    val bodies = context.bodies
    measure(bodies.state)
    rows.count = 2
    rows.set(0, -normalX, -normalY, -angular1, normalX, normalY, angular2, lineError)
    rows.set(1, 0, 0, -1, 0, 0, 1, angleError(bodies))

  def warmStart(context: SoftContext): Unit =
    measure(context.bodies.state)
    if sliding then
      measureAxis()
      slide(context.bodies, impulse(2) + impulse(3) + impulse(4) - impulse(5))
    apply(context.bodies, impulse(0), impulse(1))

  def solve(context: SoftContext, useBias: Boolean): Unit =
    solveAxial(context, useBias)
    val bodies = context.bodies
    val state = bodies.state
    measure(state)
    val index1 = ends.index1
    val index2 = ends.index2
    val s1 = index1 * Stride
    val s2 = index2 * Stride
    var lineRight = normalX * (state(s2 + VelocityX) - state(s1 + VelocityX)) +
      normalY * (state(s2 + VelocityY) - state(s1 + VelocityY)) +
      angular2 * state(s2 + AngularVelocity) - angular1 * state(s1 + AngularVelocity)
    var turnRight = state(s2 + AngularVelocity) - state(s1 + AngularVelocity)
    var massScale = 1.0
    var impulseScale = 0.0
    if useBias then
      val softness = context.jointSoftness
      lineRight += softness.biasRate * lineError
      turnRight += softness.biasRate * angleError(bodies)
      massScale = softness.massScale
      impulseScale = softness.impulseScale
    matrix.solve(bodies.invMass(index1), bodies.invI(index1), bodies.invMass(index2), bodies.invI(index2), angular1,
      angular2, lineRight, turnRight)
    val line = -massScale * matrix.lineImpulse - impulseScale * impulse(0)
    val turn = -massScale * matrix.turnImpulse - impulseScale * impulse(1)
    impulse(0) += line
    impulse(1) += turn
    apply(bodies, line, turn)
