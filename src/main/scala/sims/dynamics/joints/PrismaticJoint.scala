package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.{PortableMath, Vector2D}

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
  * The original SiMS left this joint unfinished (deviation 4 in docs/deviations.md).
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

  /** The line's anchor on node1 and the sliding anchor on node2 (the soft step reads them too). */
  private[sims] val attachment1 = Anchor(node1, anchor1)
  private[sims] val attachment2 = Anchor(node2, anchor2)
  // The classic step's arms of the anchors.
  private val point1 = attachment1.arm()
  private val point2 = attachment2.arm()

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor1, node2, anchor2)
  // Direction of the line in body 1's own frame.
  private val localAxis = (anchor2 - anchor1).unit.rotate(-node1.rotation)
  /** The line's direction in body 1's own frame, x and y (the soft step reads them too). */
  private[sims] val localAxisX = localAxis.x
  private[sims] val localAxisY = localAxis.y

  /** Relative rotation `node2.rotation - node1.rotation` that the joint keeps: its value at creation. */
  val referenceAngle: Double = node2.rotation - node1.rotation

  /** The range `translation` is kept in (default None: no limit). Under both steps: the classic
    * step corrects it one-sidedly after the line, in velocity and in position.
    */
  var limits: Option[JointLimits] = None

  /** The motor that drives `translationSpeed` (default None; its maxForce in N). Needs the soft step. */
  var motor: Option[JointMotor] = None

  /** `translation` when the joint was made: the distance from anchor1 to anchor2, m. */
  val initialTranslation: Double = (anchor2 - anchor1).length

  /** The spring that pulls `translation` back to `initialTranslation` (default None). Needs the
    * soft step.
    */
  var spring: Option[JointSpring] = None

  override private[sims] def softStepFeature: Option[String] =
    if motor.nonEmpty then Some("a motor") else if spring.nonEmpty then Some("a spring") else super.softStepFeature

  /** How fast the sliding anchor moves along the line, relative to node1, m/s. */
  def translationSpeed: Double =
    val u = axis
    val p2 = connection2
    val relative = node2.velocityOfPoint(p2) - node1.velocityOfPoint(p2)
    relative dot u

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

  // The classic step's 2x2 system (see PrismaticMatrix).
  private val matrix = PrismaticMatrix()

  /** Solves K lambda = (lineRight, turnRight) for the geometry set by `prepare()`. */
  private def solve(lineRight: Double, turnRight: Double): Unit =
    matrix.solve(node1.invMass, node1.invI, node2.invMass, node2.invI, angular1, angular2, lineRight, turnRight)

  def correctVelocity(h: Double): Unit =
    correctLineVelocity()
    if limits.nonEmpty then correctLimit(limits.get, position = false)

  private def correctLineVelocity(): Unit =
    prepare()
    val b1 = node1
    val b2 = node2
    val lineSpeed = normalX * (b2.vx - b1.vx) + normalY * (b2.vy - b1.vy) + angular2 * b2.w - angular1 * b1.w
    val turnSpeed = b2.w - b1.w
    solve(-lineSpeed, -turnSpeed)
    val px = normalX * matrix.lineImpulse
    val py = normalY * matrix.lineImpulse
    b1.vx -= px * b1.invMass
    b1.vy -= py * b1.invMass
    b1.w -= (angular1 * matrix.lineImpulse + matrix.turnImpulse) * b1.invI
    b2.vx += px * b2.invMass
    b2.vy += py * b2.invMass
    b2.w += (angular2 * matrix.lineImpulse + matrix.turnImpulse) * b2.invI

  def correctPosition(h: Double): Unit =
    correctLinePosition()
    if limits.nonEmpty then correctLimit(limits.get, position = true)

  /** The limits' correction (an extension of SiMS's joints) along the line u: at or beyond an
    * end, a velocity that would go further out is stopped (`position` false), or a translation
    * beyond it is moved back to it (`position` true), one-sidedly, with the row
    * J = [-u, -b1, u, b2], b1 = (p2 - x1) x u, b2 = r2 x u.
    */
  private def correctLimit(range: JointLimits, position: Boolean): Unit =
    point1.update()
    point2.update()
    val u = localAxis.rotate(node1.angle)
    val reachX = point2.x - node1.x
    val reachY = point2.y - node1.y
    val b1 = reachX * u.y - reachY * u.x
    val b2 = point2.armX * u.y - point2.armY * u.x
    val k = node1.invMass + node2.invMass + node1.invI * b1 * b1 + node2.invI * b2 * b2
    if k > 0 then
      val t = u.x * (point2.x - point1.x) + u.y * (point2.y - point1.y)
      val lambda =
        if position then
          if t < range.lower then (range.lower - t) / k else if t > range.upper then (range.upper - t) / k else 0.0
        else
          val speed = u.x * (node2.vx - node1.vx) + u.y * (node2.vy - node1.vy) + b2 * node2.w - b1 * node1.w
          if (t <= range.lower && speed < 0) || (t >= range.upper && speed > 0) then -speed / k else 0.0
      if lambda != 0 then
        if position then
          node1.displace(-u.x * lambda * node1.invMass, -u.y * lambda * node1.invMass, -b1 * lambda * node1.invI)
          node2.displace(u.x * lambda * node2.invMass, u.y * lambda * node2.invMass, b2 * lambda * node2.invI)
        else
          node1.vx -= u.x * lambda * node1.invMass; node1.vy -= u.y * lambda * node1.invMass
          node1.w -= b1 * lambda * node1.invI
          node2.vx += u.x * lambda * node2.invMass; node2.vy += u.y * lambda * node2.invMass
          node2.w += b2 * lambda * node2.invI

  private def correctLinePosition(): Unit =
    prepare()
    val b1 = node1
    val b2 = node2
    val lineError = normalX * (point2.x - point1.x) + normalY * (point2.y - point1.y)
    val angleError = b2.angle - b1.angle - referenceAngle
    solve(-lineError, -angleError)
    val px = normalX * matrix.lineImpulse
    val py = normalY * matrix.lineImpulse
    b1.displace(-px * b1.invMass, -py * b1.invMass, -(angular1 * matrix.lineImpulse + matrix.turnImpulse) * b1.invI)
    b2.displace(px * b2.invMass, py * b2.invMass, (angular2 * matrix.lineImpulse + matrix.turnImpulse) * b2.invI)

  override def toString: String =
    val extras = limits.map(l => s", $l").getOrElse("") + motor.map(m => s", $m").getOrElse("") +
      spring.map(sp => s", $sp").getOrElse("")
    s"PrismaticJoint($node1, $node2, axis = $axis$extras)"
