package sims.collision.manifold

import org.scalacheck.Gen
import sims.dynamics.{Circle, Rectangle, RegularPolygon, Shape}
import sims.geometry.{ConvexPolygon, Vector2D}

/** Shapes, brute-force geometry and generators shared by the manifold specs. The shapes are
  * not part of any body, so the tests move them freely.
  */
object ManifoldFixtures:
  type Polygon = Shape & ConvexPolygon

  /** SOFTSTEP.md's default speculative distance, m. */
  val SpeculativeDistance: Double = 0.02

  /** SOFTSTEP.md's default linear slop, m. */
  val LinearSlop: Double = 0.005

  /** A point of a manifold, for comparisons. */
  final case class Point(x: Double, y: Double, separation: Double, id: Int)

  /** The points of `manifold` in order. */
  def points(manifold: Manifold): List[Point] =
    List.tabulate(manifold.pointCount)(i =>
      Point(manifold.x(i), manifold.y(i), manifold.separation(i), manifold.id(i)))

  def circle(radius: Double, x: Double, y: Double): Circle =
    val c = Circle(radius, 1); c.pos = Vector2D(x, y); c

  def box(halfWidth: Double, halfHeight: Double, x: Double, y: Double, rotation: Double = 0): Rectangle =
    val b = Rectangle(halfWidth, halfHeight, 1); b.pos = Vector2D(x, y); b.rotation = rotation; b

  /** A triangle as a user's own shape: only `vertices` given, ConvexPolygon's defaults for the rest. */
  final class Triangle(corners: IndexedSeq[Vector2D]) extends Shape with ConvexPolygon:
    val density = 1.0
    val volume = 1.0
    val I = 1.0
    def vertices: IndexedSeq[Vector2D] = corners

  /** Moves `shape` rigidly: turns it by `angle` about the origin, then shifts it by (dx, dy). */
  def moveRigidly(shape: Shape, angle: Double, dx: Double, dy: Double): Unit =
    val p = shape.pos.rotate(angle)
    shape.pos = Vector2D(p.x + dx, p.y + dy)
    shape.rotation = shape.rotation + angle

  /** Distance of (px, py) from the segment (ax, ay) - (bx, by). */
  def segmentDistance(ax: Double, ay: Double, bx: Double, by: Double, px: Double, py: Double): Double =
    val ex = bx - ax
    val ey = by - ay
    val t = math.max(0.0, math.min(1.0, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)))
    math.hypot(px - (ax + t * ex), py - (ay + t * ey))

  /** Distance of (px, py) from the outline of `shape` (a circle or a convex polygon). */
  def outlineDistance(shape: Shape, px: Double, py: Double): Double = shape match
    case c: Circle => math.abs(math.hypot(px - c.x, py - c.y) - c.radius)
    case p: ConvexPolygon => polygonOutlineDistance(p, px, py)
    case _ => throw IllegalArgumentException(s"no outline for $shape")

  /** Distance of (px, py) from the outline of the polygon. */
  def polygonOutlineDistance(polygon: ConvexPolygon, px: Double, py: Double): Double =
    val vs = polygon.vertices
    vs.indices.map { i =>
      val a = vs(i); val b = vs((i + 1) % vs.length)
      segmentDistance(a.x, a.y, b.x, b.y, px, py)
    }.min

  /** True when some side normal of either polygon separates them (with a gap of more than 0). */
  private def separatedPolygons(a: ConvexPolygon, b: ConvexPolygon): Boolean =
    (a.sides ++ b.sides).exists { side =>
      val pa = a.project(side.n0); val pb = b.project(side.n0)
      pa.upper < pb.lower || pb.upper < pa.lower
    }

  /** The distance between the shapes; 0 when they touch or overlap. */
  def distance(a: Shape, b: Shape): Double = (a, b) match
    case (c1: Circle, c2: Circle) => math.max(0.0, math.hypot(c2.x - c1.x, c2.y - c1.y) - c1.radius - c2.radius)
    case (c: Circle, p: Shape) => distance(p, c)
    case (p: ConvexPolygon, c: Circle) =>
      if p.contains(c.pos) then 0.0 else math.max(0.0, polygonOutlineDistance(p, c.x, c.y) - c.radius)
    case (p: ConvexPolygon, q: ConvexPolygon) =>
      if !separatedPolygons(p, q) then 0.0
      else
        val fromP = p.vertices.map(v => polygonOutlineDistance(q, v.x, v.y)).min
        val fromQ = q.vertices.map(v => polygonOutlineDistance(p, v.x, v.y)).min
        math.min(fromP, fromQ)
    case _ => throw IllegalArgumentException(s"no distance for $a and $b")

  /** A rectangle or a regular polygon of random size and rotation, centred at (x, y). */
  def polygonAt(x: Double, y: Double): Gen[Polygon] =
    for
      shape <- Gen.oneOf(
        for hw <- Gen.choose(0.1, 2.0); hh <- Gen.choose(0.1, 2.0) yield Rectangle(hw, hh, 1),
        for n <- Gen.choose(3, 8); r <- Gen.choose(0.1, 2.0) yield RegularPolygon(n, r, 1))
      rotation <- Gen.choose(-math.Pi, math.Pi)
    yield
      shape.pos = Vector2D(x, y)
      shape.rotation = rotation
      shape

  /** A circle of random radius centred at (x, y). */
  def circleAt(x: Double, y: Double): Gen[Circle] =
    for r <- Gen.choose(0.05, 1.5) yield circle(r, x, y)

  /** A position near the origin. */
  val position: Gen[Vector2D] = for x <- Gen.choose(-3.0, 3.0); y <- Gen.choose(-3.0, 3.0) yield Vector2D(x, y)

  /** Places `b` along the unit `direction` from `a`'s centre so that the shapes are `gap` apart
    * (gap > 0), touch (0), or overlap (gap < 0: `b` pushed |gap| further towards `a` from
    * touching, but at most halfway to `a`'s centre). Distance along a line of translation is
    * convex, so bisection finds it.
    */
  def placeAtGap(a: Shape, b: Shape, direction: Vector2D, gap: Double): Unit =
    def at(t: Double): Unit = b.pos = a.pos + direction * t
    def distanceAt(t: Double): Double = { at(t); distance(a, b) }
    var far = 1.0
    while distanceAt(far) <= math.max(gap, 0.0) do far *= 2
    var near = 0.0 // the centres coincide: the shapes overlap
    val target = math.max(gap, 0.0)
    for _ <- 1 to 100 do
      val middle = 0.5 * (near + far)
      if distanceAt(middle) <= target then near = middle else far = middle
    // Pushed in at most halfway to the centre: distinct centres keep the laws well defined.
    at(if gap > 0 then far else math.max(0.5 * near, near + gap))

  /** A unit direction. */
  val direction: Gen[Vector2D] = Gen.choose(-math.Pi, math.Pi).map(angle => Vector2D(math.cos(angle), math.sin(angle)))

  /** Gaps from well into overlap to farther apart than the speculative distance. */
  val gap: Gen[Double] = Gen.oneOf(
    Gen.choose(-0.3, -1e-6), Gen.choose(1e-6, SpeculativeDistance), Gen.choose(SpeculativeDistance + 1e-6, 0.1))
