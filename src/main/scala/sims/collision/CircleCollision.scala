package sims.collision

import sims.dynamics.Circle
import sims.geometry.Vector2D

/** Collision of two circles. Normal: from the centre of `circle1` to that of `circle2`
  * (straight up if the centres coincide); one point: on the outline of `circle1`,
  * at `c1 + n (d - r2)` with d the distance of the centres.
  */
final class CircleCollision(circle1: Circle, circle2: Circle) extends Collision:
  val shape1: Circle = circle1
  val shape2: Circle = circle2

  private val distance = math.sqrt(
    (circle2.x - circle1.x) * (circle2.x - circle1.x) + (circle2.y - circle1.y) * (circle2.y - circle1.y))
  override private[sims] val normalX: Double = if distance == 0 then 0.0 else (circle2.x - circle1.x) / distance
  override private[sims] val normalY: Double = if distance == 0 then 1.0 else (circle2.y - circle1.y) / distance
  private val px = circle1.x + normalX * (distance - circle2.radius)
  private val py = circle1.y + normalY * (distance - circle2.radius)

  def normal: Vector2D = Vector2D(normalX, normalY)
  def points: Iterable[Vector2D] = List(Vector2D(px, py))
  override private[sims] def pointCount: Int = 1
  override private[sims] def pointX(i: Int): Double = px
  override private[sims] def pointY(i: Int): Double = py

/** The circle-circle narrowphase test. */
object CircleCollision:
  /** True when the circles touch or overlap: `|c1 - c2| - (r1 + r2) <= 0`. */
  def colliding(c1: Circle, c2: Circle): Boolean =
    val dx = c1.x - c2.x
    val dy = c1.y - c2.y
    math.sqrt(dx * dx + dy * dy) - (c1.radius + c2.radius) <= 0
