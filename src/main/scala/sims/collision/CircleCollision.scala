package sims.collision

import sims.dynamics.Circle
import sims.geometry.{Projection, Reach, Vector2D}

/** Collision of two circles. Normal: from the centre of `circle1` to that of `circle2`
  * (straight up if the centres coincide); one point: on the outline of `circle1`,
  * at `c1 + n (d - r2)` with d the distance of the centres.
  */
final class CircleCollision(circle1: Circle, circle2: Circle) extends Collision:
  private var first: Circle = circle1
  private var second: Circle = circle2
  override private[sims] def solvedInPlace: Boolean = true
  ensureCapacity(1)
  compute(circle1, circle2)

  def shape1: Circle = first
  def shape2: Circle = second

  /** Recomputes this collision for the two circles from their current positions. */
  private[collision] def compute(c1: Circle, c2: Circle): Unit =
    compute(c1, c2, math.sqrt(CircleCollision.centreDistanceSquared(c1, c2)))

  /** `compute` with the distance of the centres already known (from the test). */
  private[collision] def compute(c1: Circle, c2: Circle, distance: Double): Unit =
    first = c1
    second = c2
    normalX = if distance == 0 then 0.0 else (c2.x - c1.x) / distance
    normalY = if distance == 0 then 1.0 else (c2.y - c1.y) / distance
    pointXs(0) = c1.x + normalX * (distance - c2.radius)
    pointYs(0) = c1.y + normalY * (distance - c2.radius)
    pointCount = 1

  /** The contact's position correction, with the overlap of the two discs along the normal
    * written out: the same numbers as the general rule, without its calls through `Shape`.
    */
  override def correctPosition(h: Double): Unit =
    val c1 = first
    val c2 = second
    val nx = normalX
    val ny = normalY
    val centre1 = c1.x * nx + c1.y * ny
    val centre2 = c2.x * nx + c2.y * ny
    val overlap = Projection.overlap(centre1 - c1.radius, centre1 + c1.radius, centre2 - c2.radius, centre2 + c2.radius)
    Collision.correctPositionAt(c1.body, c2.body, pointXs(0), pointYs(0), nx, ny, overlap)

  def normal: Vector2D = Vector2D(normalX, normalY)
  def points: Iterable[Vector2D] = List(Vector2D(pointXs(0), pointYs(0)))

/** The circle-circle narrowphase test. */
object CircleCollision:
  /** True when the circles touch or overlap: `|c1 - c2| - (r1 + r2) <= 0`. */
  def colliding(c1: Circle, c2: Circle): Boolean = Reach.within(centreDistanceSquared(c1, c2), c1.radius + c2.radius)

  /** The square of the centres' distance; the same value as `colliding` and `compute` use (the
    * squares of c1 - c2 and c2 - c1 are identical), so the narrowphase computes it once for both.
    */
  private[collision] inline def centreDistanceSquared(c1: Circle, c2: Circle): Double =
    (c2.x - c1.x) * (c2.x - c1.x) + (c2.y - c1.y) * (c2.y - c1.y)
