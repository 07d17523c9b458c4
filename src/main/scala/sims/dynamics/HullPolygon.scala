package sims.dynamics

import sims.geometry.Vector2D

/** A convex polygon around any points: their convex hull, with a density (kg/m^2). Area,
  * centroid and moment of inertia come from the hull's vertices. The shape's centre (`pos`)
  * starts at the hull's centroid, so the polygon covers the given points until it is moved;
  * its `vertices` are the hull's corners, counter-clockwise. Points inside the hull or on its
  * sides are dropped. As a [[Polygon]] it collides through the built-in polygon methods of both
  * steps.
  */
final class HullPolygon private (val points: IndexedSeq[Vector2D], val density: Double, hull: HullPolygon.Hull)
    extends Polygon(hull.corners):
  Shape.requirePositive("density", density)

  /** The hull's area. */
  val volume: Double = hull.area

  /** density times the hull's polar moment about its centroid. */
  val I: Double = density * hull.polarMoment

  place(hull.centroidX, hull.centroidY, 0)

  override def toString: String =
    s"HullPolygon(${hull.corners.length} corners, density = $density, pos = $pos)"

/** Construction of [[HullPolygon]]: the hull, its checks and its mass properties. */
object HullPolygon:
  /** Points closer to the line through two others than this share of the points' extent (in
    * the cross product's units, extent squared) count as on it: such near-duplicates and
    * near-collinear points would give sides of no length or direction.
    */
  private val Tolerance = 1e-9

  /** The convex hull of `points` as a shape of the given density. Fails, naming `points`,
    * unless there are at least 3 distinct points, not all on one line, all finite.
    */
  def apply(points: Seq[Vector2D], density: Double = sims.Defaults.Density): HullPolygon =
    if points == null then throw IllegalArgumentException("points must not be null")
    val kept = IndexedSeq.from(points)
    new HullPolygon(kept, density, hullOf(kept))

  /** The hull's corners around its centroid, and its area, centroid and polar moment (per
    * unit density, about the centroid).
    */
  private final case class Hull(corners: IndexedSeq[Vector2D], area: Double, centroidX: Double, centroidY: Double,
      polarMoment: Double)

  private def hullOf(points: IndexedSeq[Vector2D]): Hull =
    for (p, i) <- points.zipWithIndex do
      if p == null || !p.isFinite then throw IllegalArgumentException(s"points must be finite, got $p at index $i")
    val distinct = points.distinct.length
    if distinct < 3 then
      throw IllegalArgumentException(s"points must hold at least 3 distinct points, got $distinct: ${points.mkString(", ")}")
    val corners = monotoneChain(points)
    if corners.length < 3 then
      throw IllegalArgumentException(s"points must not all lie on one line, got ${points.mkString(", ")}")
    massProperties(corners)

  /** Andrew's monotone chain: the hull's corners counter-clockwise, from the lowest x (then y),
    * points on a side or within the tolerance of one left out.
    */
  private def monotoneChain(points: IndexedSeq[Vector2D]): IndexedSeq[Vector2D] =
    val sorted = points.distinct.sortBy(p => (p.x, p.y))
    val extent = math.max(sorted.last.x - sorted.head.x, sorted.map(_.y).max - sorted.map(_.y).min)
    val least = Tolerance * extent * extent
    def turnsLeft(o: Vector2D, a: Vector2D, b: Vector2D) = ((a - o) cross (b - o)) > least
    def half(ordered: IndexedSeq[Vector2D]): List[Vector2D] = // reversed: the last corner first
      ordered.foldLeft(List.empty[Vector2D]) { (chain, p) =>
        var kept = chain
        while kept.lengthCompare(2) >= 0 && !turnsLeft(kept.tail.head, kept.head, p) do kept = kept.tail
        p :: kept
      }
    val lower = half(sorted).reverse
    val upper = half(sorted.reverse).reverse
    // Each half ends where the other starts.
    (lower.init ++ upper.init).toIndexedSeq

  /** Area, centroid and polar moment of the polygon, summed over the triangles from its first
    * corner (nearer numbers than from the origin); then the corners around the centroid.
    */
  private def massProperties(corners: IndexedSeq[Vector2D]): Hull =
    val origin = corners.head
    var area, sumX, sumY, moment = 0.0
    for i <- 1 until corners.length - 1 do
      val e1 = corners(i) - origin
      val e2 = corners(i + 1) - origin
      val twice = e1 cross e2 // twice the triangle's area
      area += twice / 2
      sumX += twice / 2 * (e1.x + e2.x) / 3
      sumY += twice / 2 * (e1.y + e2.y) / 3
      // The triangle (0, e1, e2)'s polar moment about 0: twice/12 (e1.e1 + e1.e2 + e2.e2).
      moment += twice / 12 * ((e1 dot e1) + (e1 dot e2) + (e2 dot e2))
    val cx = sumX / area
    val cy = sumY / area
    val centroid = Vector2D(origin.x + cx, origin.y + cy)
    // Parallel axes: from the first corner to the centroid.
    Hull(corners.map(_ - centroid), area, centroid.x, centroid.y, moment - area * (cx * cx + cy * cy))
