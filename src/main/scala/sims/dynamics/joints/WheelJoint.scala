package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** A wheel on a suspension: `node2` (the wheel) may slide along `axis`, fixed on `node1` (the
  * chassis), held by the suspension `spring`, within `limits`, and turns freely, or driven by
  * its `motor`: a car's wheel. Box2D's wheel joint.
  *
  * The constraint: with p1 = x1 + r1 on the line, p2 = x2 + r2 the wheel's point (both at
  * `anchor` when made), d = p2 - p1, u the axis and n = u.leftNormal (both turning with node1),
  *   C = n . d (the wheel stays on the line),
  *   Cdot = n . (v2 - v1) + (r2 x n) w2 - ((d + r1) x n) w1;
  * along u the spring, the limits of the translation u . d (as [[PrismaticJoint]]'s), and the
  * motor on the relative turn w2 - w1 (as [[RevoluteJoint]]'s). Under the classic step (no spring,
  * motor nor limits) the line alone is corrected, in velocity and in position as SiMS corrects
  * its joints.
  *
  * @param anchor the wheel's point (its centre, usually), world coordinates at creation
  * @param axis the suspension's direction, world coordinates at creation (not zero)
  */
final class WheelJoint(val node1: Body, val node2: Body, anchor: Vector2D, axis: Vector2D) extends Joint:
  checkNodes()
  Vector2D.requireFinite("anchor", anchor)
  Vector2D.requireFinite("axis", axis)
  if axis.isNull then throw IllegalArgumentException(s"axis must not be zero, got $axis")

  /** The line's point on node1 and the wheel's point on node2 (the soft step reads them too). */
  private[sims] val attachment1 = Anchor(node1, anchor)
  private[sims] val attachment2 = Anchor(node2, anchor)
  private val point1 = attachment1.arm()
  private val point2 = attachment2.arm()

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor, node2, anchor)

  // The axis in node1's own frame.
  private val localAxis = axis.unit.rotate(-node1.rotation)
  /** The axis in node1's own frame, x and y (the soft step reads them too). */
  private[sims] val localAxisX = localAxis.x
  private[sims] val localAxisY = localAxis.y

  /** The axis the joint was made with, world coordinates then (for saving a world). */
  private[sims] val initialAxis: Vector2D = axis

  /** The suspension (default: 4 Hz, damping ratio 0.7). None: the wheel slides freely along the
    * axis, within its limits. Needs the soft step.
    */
  var spring: Option[JointSpring] = Some(JointSpring(4, 0.7))

  /** The range of the suspension's `translation` (default None). Needs the soft step. */
  var limits: Option[JointLimits] = None

  /** The motor that turns the wheel relative to node1 (default None; its maxForce a torque, N m).
    * Needs the soft step.
    */
  var motor: Option[JointMotor] = None

  override private[sims] def softStepFeature: Option[String] =
    if spring.nonEmpty then Some("a spring")
    else if motor.nonEmpty then Some("a motor")
    else if limits.nonEmpty then Some("limits")
    else super.softStepFeature

  /** The suspension's current direction (turns with node1). */
  def currentAxis: Vector2D = localAxis.rotate(node1.rotation)

  /** How far the wheel's point is along the axis from the line's point, m (0 at rest). */
  def translation: Double = (point2.position - point1.position) dot currentAxis

  /** How fast the wheel turns relative to node1, rad/s. */
  def angleSpeed: Double = node2.w - node1.w

  def correctVelocity(h: Double): Unit =
    lineRow()
    if inverseMass > 0 then
      val speed = normalX * (node2.vx - node1.vx) + normalY * (node2.vy - node1.vy) + angular2 * node2.w -
        angular1 * node1.w
      push(-speed / inverseMass, position = false)

  def correctPosition(h: Double): Unit =
    lineRow()
    if inverseMass > 0 then
      val error = normalX * (point2.x - point1.x) + normalY * (point2.y - point1.y)
      push(-error / inverseMass, position = true)

  // The line's row at the current placements (set by `lineRow`).
  private var normalX, normalY, angular1, angular2, inverseMass = 0.0

  private def lineRow(): Unit =
    point1.update()
    point2.update()
    val u = localAxis.rotate(node1.angle)
    normalX = -u.y
    normalY = u.x
    val reachX = point2.x - node1.x
    val reachY = point2.y - node1.y
    angular1 = reachX * normalY - reachY * normalX
    angular2 = point2.armX * normalY - point2.armY * normalX
    inverseMass = node1.invMass + node2.invMass + node1.invI * angular1 * angular1 + node2.invI * angular2 * angular2

  private def push(lambda: Double, position: Boolean): Unit =
    val px = normalX * lambda
    val py = normalY * lambda
    if position then
      node1.displace(-px * node1.invMass, -py * node1.invMass, -angular1 * lambda * node1.invI)
      node2.displace(px * node2.invMass, py * node2.invMass, angular2 * lambda * node2.invI)
    else
      node1.vx -= px * node1.invMass; node1.vy -= py * node1.invMass; node1.w -= angular1 * lambda * node1.invI
      node2.vx += px * node2.invMass; node2.vy += py * node2.invMass; node2.w += angular2 * lambda * node2.invI

  override def toString: String =
    val extras = spring.map(s => s", $s").getOrElse("") + limits.map(l => s", $l").getOrElse("") +
      motor.map(m => s", $m").getOrElse("")
    s"WheelJoint($node1, $node2, anchor = $anchor, axis = $axis$extras)"
