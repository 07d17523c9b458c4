package sims.collision.manifold

import org.scalacheck.Gen
import sims.dynamics.{Capsule, Circle, Edge, Rectangle, RegularPolygon, RoundedSegment, Shape}
import sims.geometry.{ConvexPolygon, Vector2D}

/** Shapes, brute-force geometry and generators shared by the manifold specs. The shapes are
  * not part of any body, so the tests move them freely.
  */
object ManifoldFixtures:
  type Polygon = Shape & ConvexPolygon

  /** The soft step's default speculative distance, m. */
  val SpeculativeDistance: Double = 0.02

  /** The soft step's default linear slop, m. */
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

  def capsule(halfLength: Double, radius: Double, x: Double, y: Double, rotation: Double = 0): Capsule =
    val c = Capsule(halfLength, radius, 1); c.pos = Vector2D(x, y); c.rotation = rotation; c

  def edge(x1: Double, y1: Double, x2: Double, y2: Double): Edge = Edge(Vector2D(x1, y1), Vector2D(x2, y2))

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

  /** Distance of (px, py) from the core of a capsule or an edge. */
  def coreDistance(s: RoundedSegment, px: Double, py: Double): Double =
    segmentDistance(s.vertex1.x, s.vertex1.y, s.vertex2.x, s.vertex2.y, px, py)

  /** True if the segments a-b and c-d cross or touch. */
  def segmentsMeet(a: Vector2D, b: Vector2D, c: Vector2D, d: Vector2D): Boolean =
    def side(p: Vector2D, q: Vector2D, r: Vector2D) = math.signum((q - p) cross (r - p))
    def within(p: Vector2D, q: Vector2D, r: Vector2D) = // r on the line p-q: between them?
      math.min(p.x, q.x) <= r.x && r.x <= math.max(p.x, q.x) && math.min(p.y, q.y) <= r.y && r.y <= math.max(p.y, q.y)
    val (s1, s2, s3, s4) = (side(a, b, c), side(a, b, d), side(c, d, a), side(c, d, b))
    (s1 * s2 < 0 && s3 * s4 < 0) ||
    (s1 == 0 && within(a, b, c)) ||
    (s2 == 0 && within(a, b, d)) ||
    (s3 == 0 && within(c, d, a)) ||
    (s4 == 0 && within(c, d, b))

  /** Distance between the segments a-b and c-d: 0 if they meet, else the least end-to-segment distance. */
  def segmentsDistance(a: Vector2D, b: Vector2D, c: Vector2D, d: Vector2D): Double =
    if segmentsMeet(a, b, c, d) then 0.0
    else
      Seq(segmentDistance(a.x, a.y, b.x, b.y, c.x, c.y), segmentDistance(a.x, a.y, b.x, b.y, d.x, d.y),
        segmentDistance(c.x, c.y, d.x, d.y, a.x, a.y), segmentDistance(c.x, c.y, d.x, d.y, b.x, b.y)).min

  /** Distance between a convex polygon and a segment: 0 if the segment enters the polygon. */
  def polygonSegmentDistance(p: ConvexPolygon, a: Vector2D, b: Vector2D): Double =
    if p.contains(a) || p.contains(b) then 0.0 else p.sides.map(side => segmentsDistance(side.vertex1, side.vertex2, a, b)).min

  /** Distance of (px, py) from the outline of `shape` (a circle, a convex polygon, a capsule or an edge). */
  def outlineDistance(shape: Shape, px: Double, py: Double): Double = shape match
    case c: Circle => math.abs(math.hypot(px - c.x, py - c.y) - c.radius)
    case s: RoundedSegment => math.abs(coreDistance(s, px, py) - s.radius)
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
  private def separatedPolygons(a: ConvexPolygon, b: ConvexPolygon): Boolean = (a.sides ++ b.sides).exists { side =>
    val pa = a.project(side.n0); val pb = b.project(side.n0)
    pa.upper < pb.lower || pb.upper < pa.lower
  }

  /** The distance between the shapes; 0 when they touch or overlap. */
  def distance(a: Shape, b: Shape): Double = (a, b) match
    case (c1: Circle, c2: Circle) => math.max(0.0, math.hypot(c2.x - c1.x, c2.y - c1.y) - c1.radius - c2.radius)
    case (s: RoundedSegment, c: Circle) => math.max(0.0, coreDistance(s, c.x, c.y) - s.radius - c.radius)
    case (c: Circle, s: RoundedSegment) => distance(s, c)
    case (s: RoundedSegment, t: RoundedSegment) =>
      math.max(0.0, segmentsDistance(s.vertex1, s.vertex2, t.vertex1, t.vertex2) - s.radius - t.radius)
    case (p: ConvexPolygon, s: RoundedSegment) => math.max(0.0, polygonSegmentDistance(p, s.vertex1, s.vertex2) - s.radius)
    case (s: RoundedSegment, p: ConvexPolygon) => distance(p, s)
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

  /** A capsule of random size and rotation, or (one in four) an edge, centred at (x, y). */
  def capsuleAt(x: Double, y: Double): Gen[RoundedSegment] =
    for
      halfLength <- Gen.choose(0.1, 2.0)
      radius <- Gen.choose(0.05, 1.0)
      isEdge <- Gen.choose(0, 3).map(_ == 0)
      rotation <- Gen.choose(-math.Pi, math.Pi)
    yield
      val shape = if isEdge then edge(-halfLength, 0, halfLength, 0) else Capsule(halfLength, radius, 1)
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

  /** Pairs of `first` and `second` shapes (made at the given centres), from deep overlap to
    * farther apart than the speculative distance (or at the `gaps` given).
    */
  def pairsOf[A <: Shape, B <: Shape](first: (Double, Double) => Gen[A], second: (Double, Double) => Gen[B],
      gaps: Gen[Double] = gap): Gen[(A, B)] =
    for
      p <- position
      a <- first(p.x, p.y)
      b <- second(0, 0)
      u <- direction
      g <- gaps
    yield
      placeAtGap(a, b, u, g)
      (a, b)

  /** A unit direction. */
  val direction: Gen[Vector2D] = Gen.choose(-math.Pi, math.Pi).map(angle => Vector2D(math.cos(angle), math.sin(angle)))

  /** Gaps from well into overlap to farther apart than the speculative distance. */
  val gap: Gen[Double] = Gen.oneOf(
    Gen.choose(-0.3, -1e-6), Gen.choose(1e-6, SpeculativeDistance), Gen.choose(SpeculativeDistance + 1e-6, 0.1))
