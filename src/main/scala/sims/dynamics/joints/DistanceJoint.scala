package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** Keeps the distance between two anchor points, one on each body, constant (documentation 4.9).
  *
  * Derivation, with x = connection2 - connection1, u = x / |x| and r1, r2 the arms from the
  * centres to the connection points:
  *   C     = |x| - distance
  *   Cdot  = u . (v2 + w2 x r2 - v1 - w1 x r1)
  *   J     = [-u, -(r1 x u), u, r2 x u]
  *   J M^-1 J^T = 1/m1 + (r1 x u)^2 / I1 + 1/m2 + (r2 x u)^2 / I2   (its inverse: m)
  * Velocity: lambda = -m Cdot, impulse u lambda on body 2 and its opposite on body 1.
  * Position: P = -u m C moves and turns both bodies directly (velocities unchanged).
  *
  * @param anchor1 point on node1, world coordinates at creation
  * @param anchor2 point on node2, world coordinates at creation
  */
final class DistanceJoint(val node1: Body, anchor1: Vector2D, val node2: Body, anchor2: Vector2D)
    extends Joint:
  checkNodes()
  Vector2D.requireFinite("anchor1", anchor1)
  Vector2D.requireFinite("anchor2", anchor2)

  /** The anchors on each body (the soft step reads them too). */
  private[sims] val attachment1 = Anchor(node1, anchor1)
  private[sims] val attachment2 = Anchor(node2, anchor2)
  // The classic step's arms of the anchors.
  private val a1 = attachment1.arm()
  private val a2 = attachment2.arm()

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor1, node2, anchor2)

  /** The distance kept between the connection points: their distance at creation. */
  val distance: Double = (anchor2 - anchor1).length
  if distance == 0 then
    throw IllegalArgumentException(s"anchor1 and anchor2 must differ, both are $anchor1 (use a RevoluteJoint)")

  /** Current world position of the anchor on node1. */
  def connection1: Vector2D = a1.position

  /** Current world position of the anchor on node2. */
  def connection2: Vector2D = a2.position

  /** Relative position `connection2 - connection1`. */
  def x: Vector2D = connection2 - connection1

  /** Relative velocity of the connection points. */
  def v: Vector2D = node2.velocityOfPoint(connection2) - node1.velocityOfPoint(connection1)

  /** Inverse of J M^-1 J^T for direction u and arms r1, r2; 0 when both bodies are fixed. */
  private def effectiveMass(ux: Double, uy: Double, r1x: Double, r1y: Double, r2x: Double, r2y: Double): Double =
    // Anchors at the centres (arms exactly 0) leave only the inverse masses: the same sum,
    // without waiting for u.
    if r1x == 0 && r1y == 0 && r2x == 0 && r2y == 0 then centredMass
    else
      val cr1 = r1x * uy - r1y * ux
      val cr2 = r2x * uy - r2y * ux
      val invMass = node1.invMass + node1.invI * cr1 * cr1 + node2.invMass + node2.invI * cr2 * cr2
      if invMass == 0.0 then 0.0 else 1 / invMass

  /** The effective mass with both arms 0: (1/m1 + 1/m2)^-1, 0 when both bodies are fixed. */
  private def centredMass: Double =
    val invMass = node1.invMass + node2.invMass
    if invMass == 0.0 then 0.0 else 1 / invMass

  // The solvers work on doubles, with the same expressions (and so the same results) as the
  // vector formulas in the class comment; connection points are centre plus arm.

  // The joint's geometry as last measured: length |x|, direction u, arms r1 and r2, effective
  // mass m, and whether the connection points are apart (else there is no direction).
  private var length, ux, uy, r1x, r1y, r2x, r2y, m = 0.0
  private var apart = false
  // The bodies' placement counts when phase 4 last measured: velocity correction needs only
  // positions besides the velocities, and phase 4 does not move bodies, so one measurement
  // per step serves all its iterations.
  private var placements1, placements2 = -1L

  /** Measures the joint from the current positions and rotations. */
  private def measure(): Unit =
    a1.update()
    a2.update()
    val c1x = node1.x + a1.armX; val c1y = node1.y + a1.armY
    val c2x = node2.x + a2.armX; val c2y = node2.y + a2.armY
    val xx = c2x - c1x
    val xy = c2y - c1y
    length = math.sqrt(xx * xx + xy * xy)
    apart = length != 0
    if apart then
      ux = xx / length
      uy = xy / length
      r1x = c1x - node1.x; r1y = c1y - node1.y
      r2x = c2x - node2.x; r2y = c2y - node2.y
      m = effectiveMass(ux, uy, r1x, r1y, r2x, r2y)

  def correctVelocity(h: Double): Unit =
    if placements1 != node1.placements || placements2 != node2.placements then
      measure()
      placements1 = node1.placements
      placements2 = node2.placements
    if apart then
      // Relative velocity of the connection points: v + w x r of each body.
      val vx = (node2.vx - node2.w * r2y) - (node1.vx - node1.w * r1y)
      val vy = (node2.vy + node2.w * r2x) - (node1.vy + node1.w * r1x)
      val lambda = -m * (ux * vx + uy * vy)
      val impulseX = ux * lambda
      val impulseY = uy * lambda
      node1.impulseAt(-impulseX, -impulseY, r1x, r1y)
      node2.impulseAt(impulseX, impulseY, r2x, r2y)

  def correctPosition(h: Double): Unit =
    measure()
    if apart then
      val c = length - distance
      val px = -ux * m * c
      val py = -uy * m * c
      // Division by the mass (infinite when fixed), SiMS's -P/m1, where the other joints and
      // the contacts multiply by 1/m: the golden hashes pin both, and x / m and x * (1/m) differ
      // in the last bit (measured: multiplying here changes the golden "mixed" scene's hash).
      node1.displace(-(px / node1.mass), -(py / node1.mass), -((r1x * py - r1y * px) / node1.I))
      node2.displace(px / node2.mass, py / node2.mass, (r2x * py - r2y * px) / node2.I)

  override def toString: String = s"DistanceJoint($node1, $node2, distance = $distance)"
