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

  private val a1 = Anchor(node1, anchor1)
  private val a2 = Anchor(node2, anchor2)

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
  private def effectiveMass(u: Vector2D, r1: Vector2D, r2: Vector2D): Double =
    val cr1 = r1 cross u
    val cr2 = r2 cross u
    val invMass = 1 / node1.mass + 1 / node1.I * cr1 * cr1 + 1 / node2.mass + 1 / node2.I * cr2 * cr2
    if invMass == 0.0 then 0.0 else 1 / invMass

  def correctVelocity(h: Double): Unit =
    val c1 = connection1
    val c2 = connection2
    val x = c2 - c1
    if !x.isNull then // coincident points give no direction to correct along
      val u = x.unit
      val m = effectiveMass(u, c1 - node1.pos, c2 - node2.pos)
      val v = node2.velocityOfPoint(c2) - node1.velocityOfPoint(c1)
      val lambda = -m * (u dot v)
      val impulse = u * lambda
      node1.applyImpulse(-impulse, c1)
      node2.applyImpulse(impulse, c2)

  def correctPosition(h: Double): Unit =
    val c1 = connection1
    val c2 = connection2
    val x = c2 - c1
    if !x.isNull then
      val u = x.unit
      val r1 = c1 - node1.pos
      val r2 = c2 - node2.pos
      val m = effectiveMass(u, r1, r2)
      val C = x.length - distance
      val P = -u * m * C
      node1.pos = node1.pos - P / node1.mass
      node2.pos = node2.pos + P / node2.mass
      node1.rotation = node1.rotation - (r1 cross P) / node1.I
      node2.rotation = node2.rotation + (r2 cross P) / node2.I

  override def toString: String = s"DistanceJoint($node1, $node2, distance = $distance)"
