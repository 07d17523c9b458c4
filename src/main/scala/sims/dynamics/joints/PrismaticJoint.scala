package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.{PortableMath, Vector2D}
import sims.solver.soft.{JointRows, SoftAnchors, SoftBodies, SoftContext}

/** Lets body 2 slide along a line fixed on body 1, without turning relative to it.
  *
  * The line goes through anchor1 and anchor2 (world coordinates at creation); its direction u
  * and normal n = u.leftNormal turn with body 1. With p1 = x1 + r1 and p2 = x2 + r2 the anchor
  * points on each body, d = p2 - p1, the angles theta and theta0 = theta2 - theta1 at creation:
  *   C     = (n . d, theta2 - theta1 - theta0)
  *   Cdot  = (n . (v2 - v1) + (r2 x n) w2 - ((d + r1) x n) w1, w2 - w1)
  *           (dn/dt = w1 x n adds (w1 x n) . d = -(d x n) w1 to the first row)
  *   J     = [-n, -a1, n, a2; 0, -1, 0, 1] with a1 = (d + r1) x n, a2 = r2 x n
  *   K = J M^-1 J^T = [1/m1 + 1/m2 + a1^2/I1 + a2^2/I2, a1/I1 + a2/I2;
  *                     a1/I1 + a2/I2,                   1/I1 + 1/I2]
  * Velocity: solve K lambda = -Cdot; body 2 gets the linear impulse n lambda.x and the angular
  * impulse a2 lambda.x + lambda.y, body 1 the opposite linear impulse and the angular impulse
  * -(a1 lambda.x + lambda.y). These conserve linear and angular momentum exactly.
  * Position: solve K lambda = -C and move and turn both bodies by the same rule divided by the
  * masses and inertias (velocities unchanged), as the DistanceJoint does.
  * The original SiMS left this joint unfinished (deviation 4 of the SPEC).
  *
  * @param anchor1 point on node1 through which the line goes, world coordinates at creation
  * @param anchor2 point on node2 that slides along the line, world coordinates at creation
  */
final class PrismaticJoint(val node1: Body, anchor1: Vector2D, val node2: Body, anchor2: Vector2D)
    extends Joint:
  checkNodes()
  Vector2D.requireFinite("anchor1", anchor1)
  Vector2D.requireFinite("anchor2", anchor2)
  if anchor1 == anchor2 then
    throw IllegalArgumentException(s"anchor1 and anchor2 must differ to give the line a direction, both are $anchor1")

  private val point1 = Anchor(node1, anchor1)
  private val point2 = Anchor(node2, anchor2)

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor1, node2, anchor2)
  // Direction of the line in body 1's own frame.
  private val localAxis = (anchor2 - anchor1).unit.rotate(-node1.rotation)
  private val localAxisX = localAxis.x
  private val localAxisY = localAxis.y

  /** Relative rotation `node2.rotation - node1.rotation` that the joint keeps: its value at creation. */
  val referenceAngle: Double = node2.rotation - node1.rotation

  /** Current world position of the line's anchor on node1. */
  def connection1: Vector2D = point1.position

  /** Current world position of the sliding anchor on node2. */
  def connection2: Vector2D = point2.position

  /** Current unit direction of the line (from anchor1 towards anchor2 at creation; turns with node1). */
  def axis: Vector2D = localAxis.rotate(node1.rotation)

  /** Current position of the sliding anchor along the line, measured from anchor1's point, m. */
  def translation: Double = (connection2 - connection1) dot axis

  /** Current distance of the sliding anchor from the line (0 when the joint holds), m. */
  def lineError: Double = math.abs((connection2 - connection1) cross axis)

  /** Current deviation of the relative rotation from `referenceAngle` (0 when the joint holds), rad. */
  def angleError: Double = node2.rotation - node1.rotation - referenceAngle

  // Geometry of the current positions, set by `prepare()`: normal n and the angular terms.
  private var normalX, normalY, angular1, angular2: Double = 0

  /** Updates the arms, the normal n, a1 = (d + r1) x n and a2 = r2 x n from the current positions. */
  private def prepare(): Unit =
    point1.update()
    point2.update()
    val c = PortableMath.cos(node1.angle)
    val s = PortableMath.sin(node1.angle)
    // n = u.leftNormal, u = localAxis turned by body 1's rotation.
    normalX = -(localAxisX * s + localAxisY * c)
    normalY = localAxisX * c - localAxisY * s
    // d + r1 = p2 - x1
    val reachX = point2.x - node1.x
    val reachY = point2.y - node1.y
    angular1 = reachX * normalY - reachY * normalX
    angular2 = point2.armX * normalY - point2.armY * normalX

  // The solution of the last `solve`: fields rather than an object, so iterations allocate nothing.
  private var lineImpulse, turnImpulse = 0.0

  /** Solves K lambda = (lineRight, turnRight) for the geometry set by `prepare()`, K as in the
    * derivation; lambda = 0 when K is singular (both bodies fixed).
    */
  private def solve(lineRight: Double, turnRight: Double): Unit =
    val invI1 = node1.invI
    val invI2 = node2.invI
    val coupling = invI1 * angular1 + invI2 * angular2
    val k11 = node1.invMass + node2.invMass + invI1 * angular1 * angular1 + invI2 * angular2 * angular2
    val k22 = invI1 + invI2
    val determinant = k11 * k22 - coupling * coupling
    if determinant == 0 then
      lineImpulse = 0; turnImpulse = 0
    else
      lineImpulse = (k22 * lineRight - coupling * turnRight) / determinant
      turnImpulse = (k11 * turnRight - coupling * lineRight) / determinant

  def correctVelocity(h: Double): Unit =
    prepare()
    val b1 = node1
    val b2 = node2
    val lineSpeed = normalX * (b2.vx - b1.vx) + normalY * (b2.vy - b1.vy) + angular2 * b2.w - angular1 * b1.w
    val turnSpeed = b2.w - b1.w
    solve(-lineSpeed, -turnSpeed)
    val px = normalX * lineImpulse
    val py = normalY * lineImpulse
    b1.vx -= px * b1.invMass
    b1.vy -= py * b1.invMass
    b1.w -= (angular1 * lineImpulse + turnImpulse) * b1.invI
    b2.vx += px * b2.invMass
    b2.vy += py * b2.invMass
    b2.w += (angular2 * lineImpulse + turnImpulse) * b2.invI

  def correctPosition(h: Double): Unit =
    prepare()
    val b1 = node1
    val b2 = node2
    val lineError = normalX * (point2.x - point1.x) + normalY * (point2.y - point1.y)
    val angleError = b2.angle - b1.angle - referenceAngle
    solve(-lineError, -angleError)
    val px = normalX * lineImpulse
    val py = normalY * lineImpulse
    b1.displace(-px * b1.invMass, -py * b1.invMass, -(angular1 * lineImpulse + turnImpulse) * b1.invI)
    b2.displace(px * b2.invMass, py * b2.invMass, (angular2 * lineImpulse + turnImpulse) * b2.invI)

  // ---- Soft step: the same two rows, C = (n . d, theta2 - theta1 - theta0), with K at the
  // current geometry (arms and n at the start of the step turned by the bodies' rotations
  // since), solved as a soft constraint (SOFTSTEP.md section 3).

  private val accumulated = new Array[Double](2) // line, turn
  private val ends = SoftAnchors()
  private var startNormalX, startNormalY = 0.0

  override private[sims] def softImpulse: Array[Double] = accumulated

  override private[sims] def prepareSoft(context: SoftContext): Unit =
    prepare()
    ends.start(context.bodies, node1.index, node2.index, point1.armX, point1.armY, point2.armX, point2.armY)
    startNormalX = normalX; startNormalY = normalY

  // The current line error, set by `measureSoft` with the normal and angular terms.
  private var lineErrorSoft = 0.0

  /** Sets n, a1 and a2 (the fields `prepare()` sets in the classic step) and the line error
    * from the bodies' motion since the step began.
    */
  private def measureSoft(state: Array[Double]): Unit =
    ends.measure(state)
    // The normal turns with body 1.
    val s1 = ends.index1 * SoftBodies.Stride
    val c1 = state(s1 + 6); val sn1 = state(s1 + 7)
    normalX = c1 * startNormalX - sn1 * startNormalY
    normalY = sn1 * startNormalX + c1 * startNormalY
    // d + r1 = p2 - x1
    val reachX = ends.centresX + ends.arm2X
    val reachY = ends.centresY + ends.arm2Y
    angular1 = reachX * normalY - reachY * normalX
    angular2 = ends.arm2X * normalY - ends.arm2Y * normalX
    lineErrorSoft = normalX * (reachX - ends.arm1X) + normalY * (reachY - ends.arm1Y)

  /** Applies the line impulse `line` and the turn impulse `turn` to both bodies. */
  private def applySoft(bodies: SoftBodies, line: Double, turn: Double): Unit =
    val state = bodies.state
    val index1 = ends.index1
    val index2 = ends.index2
    val s1 = index1 * SoftBodies.Stride
    val s2 = index2 * SoftBodies.Stride
    val px = normalX * line
    val py = normalY * line
    state(s1) -= px * bodies.invMass(index1)
    state(s1 + 1) -= py * bodies.invMass(index1)
    state(s1 + 2) -= (angular1 * line + turn) * bodies.invI(index1)
    state(s2) += px * bodies.invMass(index2)
    state(s2 + 1) += py * bodies.invMass(index2)
    state(s2 + 2) += (angular2 * line + turn) * bodies.invI(index2)

  override private[sims] def directRows: Int = 2

  override private[sims] def rowsSoft(context: SoftContext, rows: JointRows): Unit =
    val bodies = context.bodies
    val state = bodies.state
    measureSoft(state)
    val index1 = ends.index1
    val index2 = ends.index2
    val angleError = (bodies.startAngle(index2) + state(index2 * SoftBodies.Stride + 5)) -
      (bodies.startAngle(index1) + state(index1 * SoftBodies.Stride + 5)) - referenceAngle
    rows.count = 2
    rows.set(0, -normalX, -normalY, -angular1, normalX, normalY, angular2, lineErrorSoft)
    rows.set(1, 0, 0, -1, 0, 0, 1, angleError)

  override private[sims] def warmStartSoft(context: SoftContext): Unit =
    measureSoft(context.bodies.state)
    applySoft(context.bodies, accumulated(0), accumulated(1))

  override private[sims] def solveSoft(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val state = bodies.state
    measureSoft(state)
    val index1 = ends.index1
    val index2 = ends.index2
    val s1 = index1 * SoftBodies.Stride
    val s2 = index2 * SoftBodies.Stride
    var lineRight = normalX * (state(s2) - state(s1)) + normalY * (state(s2 + 1) - state(s1 + 1)) +
      angular2 * state(s2 + 2) - angular1 * state(s1 + 2)
    var turnRight = state(s2 + 2) - state(s1 + 2)
    var massScale = 1.0
    var impulseScale = 0.0
    if useBias then
      val softness = context.jointSoftness
      val angleError = (bodies.startAngle(index2) + state(s2 + 5)) - (bodies.startAngle(index1) + state(s1 + 5)) - referenceAngle
      lineRight += softness.biasRate * lineErrorSoft
      turnRight += softness.biasRate * angleError
      massScale = softness.massScale
      impulseScale = softness.impulseScale
    solve(lineRight, turnRight)
    val line = -massScale * lineImpulse - impulseScale * accumulated(0)
    val turn = -massScale * turnImpulse - impulseScale * accumulated(1)
    accumulated(0) += line
    accumulated(1) += turn
    applySoft(bodies, line, turn)

  override def toString: String = s"PrismaticJoint($node1, $node2, axis = $axis)"
