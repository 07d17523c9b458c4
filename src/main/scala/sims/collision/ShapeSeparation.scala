package sims.collision

import sims.collision.narrowphase.PairFunctions
import sims.dynamics.{RoundedSegment, Shape}
import sims.geometry.{ConvexPolygon, PolygonMath, Segment}

/** How far apart two shapes of the built-in kinds are, and along which direction: the contact
  * events' hysteresis (is an open pair still within reach?) and the bullets' time of impact (how
  * far can a body move before it meets a fixed shape?). Allocation-free.
  *
  * The separation is the distance between the two outlines when they are apart (exact: the
  * closest points of the two shapes, the normal joining them), and minus the depth of overlap
  * when they overlap (the separating-axis depth along the side normals, as the narrowphase
  * measures it; a circle or a capsule counts its radius around its centre or core). The normal
  * is a unit vector from the first shape towards the second along which the two shapes'
  * projections are `distance` apart: moving the second shape by `d` changes their gap along it
  * by `d . normal`.
  */
private[sims] final class ShapeSeparation:
  /** Distance between the outlines found by the last `measure` (negative: depth of overlap), m. */
  var distance: Double = 0
  /** x of the unit normal from the first shape towards the second. */
  var normalX: Double = 0
  /** y of the unit normal. */
  var normalY: Double = 1

  /** Records distance `d` and normal (nx, ny); true, for the measures to return. */
  private[collision] def set(d: Double, nx: Double, ny: Double): Boolean =
    distance = d
    normalX = nx
    normalY = ny
    true

  /** Turns the normal round (for a pair measured the other way). */
  private[collision] def flip(): Boolean =
    normalX = -normalX
    normalY = -normalY
    true

  /** Measures `a` against `b` into `distance`, `normalX` and `normalY` through the pair's entry
    * of the narrowphase registry; false (and nothing changed) when either is not one of the
    * built-in kinds (circle, convex polygon, capsule or edge).
    */
  def measure(a: Shape, b: Shape): Boolean =
    val functions = PairFunctions.of(a, b)
    functions != null && functions.separation(a, b, this)

  /** Whether `a` and `b` are convex polygons with a vertex each at most `reach` apart: then the
    * polygons are at most `reach` apart (their distance is the least over all their points),
    * which this finds without their side normals (computed again for a polygon that moved) or
    * separating axes. False says nothing.
    */
  def polygonsWithin(a: Shape, b: Shape, reach: Double): Boolean = a match
    case p: ConvexPolygon =>
      b match
        case q: ConvexPolygon =>
          val pxs = p.vertexXs; val pys = p.vertexYs
          val qxs = q.vertexXs; val qys = q.vertexYs
          val limit = reach * reach
          var found = false
          var i = 0
          while !found && i < pxs.length do
            var j = 0
            while !found && j < qxs.length do
              val dx = qxs(j) - pxs(i)
              val dy = qys(j) - pys(i)
              found = dx * dx + dy * dy <= limit
              j += 1
            i += 1
          found
        case _ => false
    case _ => false

  /** Two discs: the line through their centres. */
  private[collision] def points(ax: Double, ay: Double, ra: Double, bx: Double, by: Double, rb: Double): Boolean =
    val dx = bx - ax
    val dy = by - ay
    val d = math.sqrt(dx * dx + dy * dy)
    if d > 0 then set(d - ra - rb, dx / d, dy / d) else set(-ra - rb, 0, 1)

  /** A polygon and a disc of centre (cx, cy): inside, the side of least depth; outside, the
    * nearest point of the outline.
    */
  private[collision] def polygonPoint(polygon: ConvexPolygon, cx: Double, cy: Double, radius: Double): Boolean =
    val xs = polygon.vertexXs
    val ys = polygon.vertexYs
    val nxs = polygon.sideNormalXs
    val nys = polygon.sideNormalYs
    val count = xs.length
    val side = PolygonMath.farthestSide(xs, ys, nxs, nys, count, cx, cy)
    val best = PolygonMath.sideDistance(xs, ys, nxs, nys, side, cx, cy)
    if best <= 0 then set(best - radius, nxs(side), nys(side))
    else
      nearestOnOutline(xs, ys, count, cx, cy)
      val dx = cx - nearestX
      val dy = cy - nearestY
      val d = math.sqrt(dx * dx + dy * dy)
      set(d - radius, dx / d, dy / d)

  /** A capsule's core and a disc of centre (cx, cy). */
  private[collision] def segmentPoint(segment: RoundedSegment, cx: Double, cy: Double, radius: Double): Boolean =
    val xs = segment.coreXs
    val ys = segment.coreYs
    closestOnSegment(xs(0), ys(0), xs(1), ys(1), cx, cy)
    val dx = cx - nearestX
    val dy = cy - nearestY
    val d = math.sqrt(dx * dx + dy * dy)
    if d > 0 then set(d - segment.radius - radius, dx / d, dy / d)
    else set(-segment.radius - radius, segment.coreNormalXs(0), segment.coreNormalYs(0))

  /** Two convex polygons: apart, the closest pair of a vertex and a side; overlapping, the
    * side normal of least depth (separating axes).
    */
  private[collision] def polygons(a: ConvexPolygon, b: ConvexPolygon): Boolean =
    val axs = a.vertexXs; val ays = a.vertexYs
    val bxs = b.vertexXs; val bys = b.vertexYs
    axis(axs, ays, a.sideNormalXs, a.sideNormalYs, bxs, bys)
    val depthA = axisGap; val axisAX = axisX; val axisAY = axisY
    axis(bxs, bys, b.sideNormalXs, b.sideNormalYs, axs, ays)
    if depthA >= axisGap then
      if depthA > 0 then nearestBetween(axs, ays, axs.length, bxs, bys, bxs.length, 0)
      else set(depthA, axisAX, axisAY)
    else if axisGap > 0 then nearestBetween(axs, ays, axs.length, bxs, bys, bxs.length, 0)
    else set(axisGap, -axisX, -axisY)

  /** A polygon and a capsule: its core counts as a polygon of two vertices, grown by its radius. */
  private[collision] def polygonSegment(polygon: ConvexPolygon, segment: RoundedSegment): Boolean =
    val pxs = polygon.vertexXs; val pys = polygon.vertexYs
    val sxs = segment.coreXs; val sys = segment.coreYs
    axis(pxs, pys, polygon.sideNormalXs, polygon.sideNormalYs, sxs, sys)
    val depthP = axisGap; val axisPX = axisX; val axisPY = axisY
    axis(sxs, sys, segment.coreNormalXs, segment.coreNormalYs, pxs, pys)
    val gap = math.max(depthP, axisGap)
    if gap > 0 then nearestBetween(pxs, pys, pxs.length, sxs, sys, 2, segment.radius)
    else if depthP >= axisGap then set(depthP - segment.radius, axisPX, axisPY)
    else set(axisGap - segment.radius, -axisX, -axisY)

  /** Two capsules' cores: apart, their closest points; crossing, the core normal of least depth. */
  private[collision] def segments(a: RoundedSegment, b: RoundedSegment): Boolean =
    val axs = a.coreXs; val ays = a.coreYs
    val bxs = b.coreXs; val bys = b.coreYs
    val radii = a.radius + b.radius
    if crossing(axs(0), ays(0), axs(1), ays(1), bxs(0), bys(0), bxs(1), bys(1)) then
      axis(axs, ays, a.coreNormalXs, a.coreNormalYs, bxs, bys)
      val depthA = axisGap; val axisAX = axisX; val axisAY = axisY
      axis(bxs, bys, b.coreNormalXs, b.coreNormalYs, axs, ays)
      if depthA >= axisGap then set(depthA - radii, axisAX, axisAY)
      else set(axisGap - radii, -axisX, -axisY)
    else
      nearestBetween(axs, ays, 2, bxs, bys, 2, radii)
      if distance == -radii then set(-radii, a.coreNormalXs(0), a.coreNormalYs(0)) // touching cores
      else true

  /** True if the segments cross each other (each one's ends strictly on both sides of the other). */
  private def crossing(ax: Double, ay: Double, bx: Double, by: Double, cx: Double, cy: Double, dx: Double,
      dy: Double): Boolean =
    def side(px: Double, py: Double, qx: Double, qy: Double, rx: Double, ry: Double): Double = (qx - px) * (ry - py) - (qy - py) * (rx - px)
    val c1 = side(ax, ay, bx, by, cx, cy)
    val c2 = side(ax, ay, bx, by, dx, dy)
    val c3 = side(cx, cy, dx, dy, ax, ay)
    val c4 = side(cx, cy, dx, dy, bx, by)
    c1 * c2 < 0 && c3 * c4 < 0

  // The results of `axis`, `closestOnSegment` and `nearestOnOutline` (each object is used by
  // one world: no allocation, no sharing between threads). Callers copy them before the next call.
  private var axisGap, axisX, axisY = 0.0
  private var nearestX, nearestY = 0.0

  /** The side normal of the first polygon (vertices `xs`, `ys`, normals `nxs`, `nys`) along which
    * the other polygon's vertices lie farthest out: `axisGap` (the gap along it, negative when
    * every such gap is negative) and the normal in `axisX`, `axisY`.
    */
  private def axis(xs: Array[Double], ys: Array[Double], nxs: Array[Double], nys: Array[Double], otherXs: Array[Double],
      otherYs: Array[Double]): Unit =
    axisGap = Double.NegativeInfinity
    var i = 0
    while i < nxs.length do
      val nx = nxs(i); val ny = nys(i)
      var lowest = Double.PositiveInfinity
      var k = 0
      while k < otherXs.length do
        val s = nx * (otherXs(k) - xs(i)) + ny * (otherYs(k) - ys(i))
        if s < lowest then lowest = s
        k += 1
      if lowest > axisGap then
        axisGap = lowest; axisX = nx; axisY = ny
      i += 1

  /** The closest point to (px, py) of the segment from (ax, ay) to (bx, by), into `nearestX`, `nearestY`. */
  private def closestOnSegment(ax: Double, ay: Double, bx: Double, by: Double, px: Double, py: Double): Unit =
    val dx = bx - ax
    val dy = by - ay
    val dd = dx * dx + dy * dy
    val t = if dd == 0 then 0.0 else ((px - ax) * dx + (py - ay) * dy) / dd
    if t <= 0 then { nearestX = ax; nearestY = ay }
    else if t >= 1 then { nearestX = bx; nearestY = by }
    else { nearestX = ax + t * dx; nearestY = ay + t * dy }

  /** The point of the outline of the polygon (or the segment, `count` 2) nearest (px, py). */
  private def nearestOnOutline(xs: Array[Double], ys: Array[Double], count: Int, px: Double, py: Double): Double =
    var best = Double.PositiveInfinity
    var bestX, bestY = 0.0
    val sides = if count == 2 then 1 else count
    var i = 0
    while i < sides do
      val j = if i + 1 == count then 0 else i + 1
      val d = Segment.distance(xs(i), ys(i), xs(j), ys(j), px, py)
      if d < best then
        best = d
        closestOnSegment(xs(i), ys(i), xs(j), ys(j), px, py)
        bestX = nearestX; bestY = nearestY
      i += 1
    nearestX = bestX
    nearestY = bestY
    best

  /** Two convex outlines that do not overlap (polygons, or segments: `count` 2): their closest
    * points are a vertex of one and a point of the other's outline. Sets the distance minus
    * `radius` and the unit normal from the first towards the second.
    */
  private def nearestBetween(axs: Array[Double], ays: Array[Double], aCount: Int, bxs: Array[Double],
      bys: Array[Double], bCount: Int, radius: Double): Boolean =
    var best = Double.PositiveInfinity
    var fromX, fromY, toX, toY = 0.0
    var k = 0
    while k < bCount do // a vertex of b against a's outline
      val d = nearestOnOutline(axs, ays, aCount, bxs(k), bys(k))
      if d < best then
        best = d; fromX = nearestX; fromY = nearestY; toX = bxs(k); toY = bys(k)
      k += 1
    k = 0
    while k < aCount do // a vertex of a against b's outline
      val d = nearestOnOutline(bxs, bys, bCount, axs(k), ays(k))
      if d < best then
        best = d; fromX = axs(k); fromY = ays(k); toX = nearestX; toY = nearestY
      k += 1
    if best > 0 then set(best - radius, (toX - fromX) / best, (toY - fromY) / best)
    else set(-radius, 0, 1) // touching outlines: the callers give their own normal
