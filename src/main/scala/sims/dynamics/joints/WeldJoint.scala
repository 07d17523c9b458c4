package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** Glues two bodies together at `anchor`: they neither move apart there nor turn relative to
  * each other, rigidly, or softly (a weld that gives, like a cantilever or a rubber mount) when
  * given a `linearHertz` or an `angularHertz`.
  *
  * The constraint: the pin of a [[RevoluteJoint]] at `anchor` (C = p2 - p1) and the relative
  * turn C = theta2 - theta1 - theta0 (Cdot = w2 - w1, effective mass 1 / (1/I1 + 1/I2)). Under
  * the classic step (rigid welds only) the pin is corrected as a revolute joint's, then the
  * turn, in velocity and in position, as SiMS corrects its joints; under the soft step each is
  * a soft constraint (with the soft step's joint stiffness, or the weld's own).
  *
  * @param anchor where the bodies are glued, world coordinates at creation
  * @param linearHertz stiffness of the pin, Hz; 0 (default) for rigid
  * @param angularHertz stiffness of the turn, Hz; 0 (default) for rigid
  * @param dampingRatio damping ratio of a soft pin or turn (default 1)
  */
final class WeldJoint(val node1: Body, val node2: Body, anchor: Vector2D, val linearHertz: Double = 0,
    val angularHertz: Double = 0, val dampingRatio: Double = 1) extends Joint:
  checkNodes()
  Vector2D.requireFinite("anchor", anchor)
  if !(linearHertz >= 0) || linearHertz.isInfinite then
    throw IllegalArgumentException(s"linearHertz must be finite and at least 0, got $linearHertz")
  if !(angularHertz >= 0) || angularHertz.isInfinite then
    throw IllegalArgumentException(s"angularHertz must be finite and at least 0, got $angularHertz")
  if !(dampingRatio >= 0) || dampingRatio.isInfinite then
    throw IllegalArgumentException(s"dampingRatio must be finite and at least 0, got $dampingRatio")

  /** The pin's point on each body (the soft step reads them too). */
  private[sims] val attachment1 = Anchor(node1, anchor)
  private[sims] val attachment2 = Anchor(node2, anchor)

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor, node2, anchor)

  /** The classic step's pin: a revolute joint at the anchor, not in any world. */
  private val pin = RevoluteJoint(node1, node2, anchor)

  /** Relative rotation `node2.rotation - node1.rotation` the weld keeps: its value at creation. */
  val referenceAngle: Double = node2.rotation - node1.rotation

  /** How far node2 has turned relative to node1 since the weld was made (0 while it holds), rad. */
  def angle: Double = node2.angle - node1.angle - referenceAngle

  /** How far apart the pin's points on the two bodies are now (0 while it holds), m. */
  def separation: Double = pin.separation

  override private[sims] def softStepFeature: Option[String] =
    if linearHertz > 0 || angularHertz > 0 then Some("a soft weld (linearHertz or angularHertz)")
    else super.softStepFeature

  def correctVelocity(h: Double): Unit =
    pin.correctVelocity(h)
    val inverse = node1.invI + node2.invI
    if inverse > 0 then
      val lambda = -(node2.w - node1.w) / inverse
      node1.w -= lambda * node1.invI
      node2.w += lambda * node2.invI

  def correctPosition(h: Double): Unit =
    pin.correctPosition(h)
    val inverse = node1.invI + node2.invI
    if inverse > 0 then
      val lambda = -angle / inverse
      node1.displace(0, 0, -lambda * node1.invI)
      node2.displace(0, 0, lambda * node2.invI)

  override def toString: String =
    s"WeldJoint($node1, $node2, anchor = $anchor, linearHertz = $linearHertz, angularHertz = $angularHertz)"
