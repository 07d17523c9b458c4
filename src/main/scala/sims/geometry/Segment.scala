package sims.geometry

/** The straight segment from `vertex1` to `vertex2`. */
final case class Segment(vertex1: Vector2D, vertex2: Vector2D):

  /** Direction vector `vertex2 - vertex1`. */
  def d: Vector2D = vertex2 - vertex1

  /** Unit direction vector. */
  def d0: Vector2D = d.unit

  /** Right normal of the direction; for a counter-clockwise polygon side it points outward. */
  def n: Vector2D = d.rightNormal

  /** Unit right normal. */
  def n0: Vector2D = n.unit

  /** Length of the segment. */
  def length: Double = d.length

  /** Shortest distance from `point` to any point of this segment. */
  def distance(point: Vector2D): Double =
    Segment.distance(vertex1.x, vertex1.y, vertex2.x, vertex2.y, point.x, point.y)

/** Allocation-free segment geometry for the narrowphase. */
object Segment:
  /** Distance from (px, py) to the segment (ax, ay)-(bx, by). */
  private[sims] def distance(ax: Double, ay: Double, bx: Double, by: Double, px: Double, py: Double): Double =
    math.sqrt(squaredDistance(ax, ay, bx, by, px, py))

  /** The square of `distance`, the same bits before the square root. */
  private[sims] def squaredDistance(ax: Double, ay: Double, bx: Double, by: Double, px: Double, py: Double): Double =
    val dx = bx - ax
    val dy = by - ay
    val dd = dx * dx + dy * dy
    val t = if dd == 0 then 0.0 else ((px - ax) * dx + (py - ay) * dy) / dd
    // Clamped ends use the vertex itself, so a vertex's distance is computed identically.
    val cx = if t <= 0 then ax else if t >= 1 then bx else ax + dx * t
    val cy = if t <= 0 then ay else if t >= 1 then by else ay + dy * t
    val ex = cx - px
    val ey = cy - py
    ex * ex + ey * ey
