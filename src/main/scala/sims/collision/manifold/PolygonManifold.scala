package sims.collision.manifold

import sims.dynamics.{RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

// Polygon-polygon manifold by the separating axis test and clipping.
//
// Separation. Side i of polygon P (from v_i, outward unit normal n_i) has the other polygon Q
// at least s_i = min over Q's vertices w of n_i . (w - v_i) beyond its line. The best side of
// each polygon is the one of greatest s_i; the reference side is the better of the two (A's
// unless B's is better by more than 0.1 linearSlop, so that ties such as a box resting flat
// on a box do not flip from step to step). If it exceeds speculativeDistance there is no
// contact.
//
// Clipping. Reference side r1 -> r2 with unit tangent t = (r2 - r1) / L and normal n. The
// incident side p1 -> p2 is the other polygon's side most anti-parallel to n; as both polygons
// run counter-clockwise it runs against t, so u1 = t . (p1 - r1) > u2 = t . (p2 - r1). The
// points of the reference side's slab have 0 <= u <= L; clipping the segment to the slab
// (Sutherland-Hodgman with its two side planes) moves p1 back to u = L if u1 > L, p2 forward
// to u = 0 if u2 < 0, and leaves nothing if the whole segment lies beyond one plane. Each
// remaining point q has separation s = n . (q - r1) and is reported midway between the
// reference line and q, at q - n s / 2, if s <= speculativeDistance. Since q lies between
// two vertices of the incident polygon, s is at least the reference side's s_i: when that is
// positive (apart), no separation is negative.
//
// Corner near corner. Apart, the closest features of the two sides may be one vertex of each
// (the two polygons meet corner to corner). Face normals under-estimate that distance, so then
// the one point is placed midway between the two vertices, with the normal from one to the
// other and the separation their true distance. A vertex pair (r, p) is the closest pair of
// the two sides when moving away from it along either side gets no nearer: with d = p - r,
// e = (other end of the reference side) - r and f = (other end of the incident side) - p,
// when d . e < 0 and d . f > 0 (the squared distance of two segments is convex in their
// parameters, so this local minimum is the minimum).
//
// Rounded polygons. A capsule or an edge is a polygon of two vertices (its core's ends) and two
// sides (the core, with its two opposite normals) grown by a radius r: each point within r of
// it. Separations along a side normal and between corners then shrink by the radii of the two
// shapes, and a point lies midway between the grown surfaces: for a clipped incident point q
// of core separation c from the reference side, the surfaces lie at rReference and
// c - rIncident along n, and the point at q - n (c + rIncident - rReference) / 2. Plain
// polygons have radius 0 and the same arithmetic as before. The separating axes of two
// convex polygons are their side normals; a polygon and a core segment need no more, so this
// serves a polygon against a capsule (two cores need the axes of their ends too: see
// CapsuleManifold).
//
// Ids: see `collide`.

/** The manifold of two convex polygons, or of a polygon and a capsule or an edge (see docs/two-solvers.md).
  */
private[sims] object PolygonManifold:

  /** Bit set in an id when polygon B gave the reference side. */
  val ReferenceIsB: Int = 1 << 30

  /** Bits below the reference side in an id: incident vertex indices are less than 2^15. */
  val SideShift: Int = 15

  /** Fills `manifold` for polygons A and B: at most two points, each with its separation at
    * most `speculativeDistance`. The id of a point is
    * `(ReferenceIsB if B gave the reference side) | referenceSide << SideShift | incidentVertex`,
    * incidentVertex being the index of the incident polygon's vertex the point was clipped from
    * (or met at a corner); so polygons of up to 2^15 vertices have distinct ids.
    */
  def collide(polygonA: Shape & ConvexPolygon, polygonB: Shape & ConvexPolygon, speculativeDistance: Double,
      linearSlop: Double, manifold: Manifold): Unit =
    collideRounded(polygonA.vertexXs, polygonA.vertexYs, polygonA.sideNormalXs, polygonA.sideNormalYs, 0,
      polygonB.vertexXs, polygonB.vertexYs, polygonB.sideNormalXs, polygonB.sideNormalYs, 0,
      speculativeDistance, linearSlop, manifold)

  /** `collide` for polygon A and capsule (or edge) B, as a polygon of two vertices (its core's
    * ends, 0 and 1) and two sides (0: the core's right side, 1: its left) with a radius.
    */
  def collide(polygonA: Shape & ConvexPolygon, capsuleB: RoundedSegment, speculativeDistance: Double,
      linearSlop: Double, manifold: Manifold): Unit =
    collideRounded(polygonA.vertexXs, polygonA.vertexYs, polygonA.sideNormalXs, polygonA.sideNormalYs, 0,
      capsuleB.coreXs, capsuleB.coreYs, capsuleB.coreNormalXs, capsuleB.coreNormalYs, capsuleB.radius,
      speculativeDistance, linearSlop, manifold)

  /** `collide` for capsule (or edge) A and polygon B (see the other way round). */
  def collide(capsuleA: RoundedSegment, polygonB: Shape & ConvexPolygon, speculativeDistance: Double,
      linearSlop: Double, manifold: Manifold): Unit =
    collideRounded(capsuleA.coreXs, capsuleA.coreYs, capsuleA.coreNormalXs, capsuleA.coreNormalYs, capsuleA.radius,
      polygonB.vertexXs, polygonB.vertexYs, polygonB.sideNormalXs, polygonB.sideNormalYs, 0,
      speculativeDistance, linearSlop, manifold)

  /** The manifold of polygons A and B given by their vertices, outward unit side normals and
    * radii (0 for a plain polygon).
    */
  private def collideRounded(aXs: Array[Double], aYs: Array[Double], aNormalXs: Array[Double],
      aNormalYs: Array[Double], radiusA: Double, bXs: Array[Double], bYs: Array[Double], bNormalXs: Array[Double],
      bNormalYs: Array[Double], radiusB: Double, speculativeDistance: Double, linearSlop: Double,
      manifold: Manifold): Unit =
    manifold.clear()
    val sideA = bestSide(aXs, aYs, aNormalXs, aNormalYs, bXs, bYs)
    val separationA = sideSeparation(aXs, aYs, aNormalXs, aNormalYs, sideA, bXs, bYs)
    val sideB = bestSide(bXs, bYs, bNormalXs, bNormalYs, aXs, aYs)
    val separationB = sideSeparation(bXs, bYs, bNormalXs, bNormalYs, sideB, aXs, aYs)
    if separationA - radiusA - radiusB <= speculativeDistance && separationB - radiusA - radiusB <= speculativeDistance then
      // Whether the cores are apart: then their nearest features may be two corners.
      val apart = separationA > 0.1 * linearSlop || separationB > 0.1 * linearSlop
      if separationB > separationA + 0.1 * linearSlop then
        clip(bXs, bYs, bNormalXs, bNormalYs, radiusB, sideB, aXs, aYs, aNormalXs, aNormalYs, radiusA,
          referenceIsB = true, apart, speculativeDistance, manifold)
      else
        clip(aXs, aYs, aNormalXs, aNormalYs, radiusA, sideA, bXs, bYs, bNormalXs, bNormalYs, radiusB,
          referenceIsB = false, apart, speculativeDistance, manifold)

  /** The side of a polygon (vertices xs, ys; outward unit side normals normalXs, normalYs) of
    * greatest separation from the polygon of vertices otherXs, otherYs (the first on ties).
    */
  private[sims] def bestSide(xs: Array[Double], ys: Array[Double], normalXs: Array[Double],
      normalYs: Array[Double], otherXs: Array[Double], otherYs: Array[Double]): Int =
    var best = 0
    var bestSeparation = Double.NegativeInfinity
    var i = 0
    while i < xs.length do
      val separation = sideSeparation(xs, ys, normalXs, normalYs, i, otherXs, otherYs)
      if separation > bestSeparation then
        bestSeparation = separation
        best = i
      i += 1
    best

  /** How far the other polygon lies beyond the line of side `side` (arrays as in `bestSide`):
    * the least n . (w - v) over its vertices w.
    */
  private[sims] def sideSeparation(xs: Array[Double], ys: Array[Double], normalXs: Array[Double],
      normalYs: Array[Double], side: Int, otherXs: Array[Double], otherYs: Array[Double]): Double =
    val normalX = normalXs(side)
    val normalY = normalYs(side)
    val startX = xs(side)
    val startY = ys(side)
    var least = Double.PositiveInfinity
    var j = 0
    while j < otherXs.length do
      val separation = normalX * (otherXs(j) - startX) + normalY * (otherYs(j) - startY)
      if separation < least then least = separation
      j += 1
    least

  /** The points of the reference side `side` of the reference polygon (vertices, normals,
    * radius) against the incident polygon.
    */
  private def clip(referenceXs: Array[Double], referenceYs: Array[Double], referenceNormalXs: Array[Double],
      referenceNormalYs: Array[Double], referenceRadius: Double, side: Int, incidentXs: Array[Double],
      incidentYs: Array[Double], incidentNormalXs: Array[Double], incidentNormalYs: Array[Double],
      incidentRadius: Double, referenceIsB: Boolean, apart: Boolean, speculativeDistance: Double,
      manifold: Manifold): Unit =
    val normalX = referenceNormalXs(side)
    val normalY = referenceNormalYs(side)
    val referenceNext = if side + 1 == referenceXs.length then 0 else side + 1
    val r1x = referenceXs(side); val r1y = referenceYs(side)
    val r2x = referenceXs(referenceNext); val r2y = referenceYs(referenceNext)

    val incidentSide = mostAntiParallelSide(incidentNormalXs, incidentNormalYs, normalX, normalY)
    val incidentNext = if incidentSide + 1 == incidentXs.length then 0 else incidentSide + 1
    val p1x = incidentXs(incidentSide); val p1y = incidentYs(incidentSide)
    val p2x = incidentXs(incidentNext); val p2y = incidentYs(incidentNext)

    // The normal leaves the reference polygon; the manifold's goes from A to B.
    val orientation = if referenceIsB then -1.0 else 1.0
    manifold.normalX = orientation * normalX
    manifold.normalY = orientation * normalY
    val idBase = (if referenceIsB then ReferenceIsB else 0) | side << SideShift
    val p1Id = idBase | incidentSide
    val p2Id = idBase | incidentNext

    val corner = apart && (
      cornerPoint(
        r1x, r1y, r2x, r2y, p1x, p1y, p2x, p2y, p1Id, orientation, referenceRadius, incidentRadius, speculativeDistance, manifold) ||
        cornerPoint(
          r1x, r1y, r2x, r2y, p2x, p2y, p1x, p1y, p2Id, orientation, referenceRadius, incidentRadius, speculativeDistance, manifold) ||
        cornerPoint(
          r2x, r2y, r1x, r1y, p1x, p1y, p2x, p2y, p1Id, orientation, referenceRadius, incidentRadius, speculativeDistance, manifold) ||
        cornerPoint(
          r2x, r2y, r1x, r1y, p2x, p2y, p1x, p1y, p2Id, orientation, referenceRadius, incidentRadius, speculativeDistance, manifold))

    if !corner then
      val length = math.sqrt((r2x - r1x) * (r2x - r1x) + (r2y - r1y) * (r2y - r1y))
      val tangentX = (r2x - r1x) / length
      val tangentY = (r2y - r1y) / length
      val u1 = tangentX * (p1x - r1x) + tangentY * (p1y - r1y)
      val u2 = tangentX * (p2x - r1x) + tangentY * (p2y - r1y)
      if u1 >= 0 && u2 <= length then // else the whole incident side lies beyond a side plane
        // Both fractions lie in (0, 1]: u1 > length >= u2 for the first, u2 < 0 <= u1 for the second.
        val fraction1 = if u1 > length then (u1 - length) / (u1 - u2) else 0.0
        val fraction2 = if u2 < 0 then -u2 / (u1 - u2) else 0.0
        addClipped(p1x + (p2x - p1x) * fraction1, p1y + (p2y - p1y) * fraction1, r1x, r1y, normalX, normalY,
          p1Id, referenceRadius, incidentRadius, speculativeDistance, manifold)
        addClipped(p2x + (p1x - p2x) * fraction2, p2y + (p1y - p2y) * fraction2, r1x, r1y, normalX, normalY,
          p2Id, referenceRadius, incidentRadius, speculativeDistance, manifold)
    if manifold.pointCount == 0 then manifold.clear() // no normal without a contact

  /** The side whose outward normal (normalXs, normalYs) is most anti-parallel to (normalX, normalY). */
  private def mostAntiParallelSide(normalXs: Array[Double], normalYs: Array[Double], normalX: Double,
      normalY: Double): Int =
    var best = 0
    var lowest = Double.PositiveInfinity
    var i = 0
    while i < normalXs.length do
      val dot = normalXs(i) * normalX + normalYs(i) * normalY
      if dot < lowest then
        lowest = dot
        best = i
      i += 1
    best

  /** Adds the clipped incident point (qx, qy) midway between the two surfaces, the reference's
    * along (normalX, normalY) from the line through (r1x, r1y), if its separation is at most
    * `speculativeDistance`.
    */
  private def addClipped(qx: Double, qy: Double, r1x: Double, r1y: Double, normalX: Double, normalY: Double,
      id: Int, referenceRadius: Double, incidentRadius: Double, speculativeDistance: Double, manifold: Manifold): Unit =
    val core = normalX * (qx - r1x) + normalY * (qy - r1y)
    val separation = core - referenceRadius - incidentRadius
    if separation <= speculativeDistance then
      val shift = core + incidentRadius - referenceRadius // twice q's distance to the middle
      manifold.addPoint(qx - normalX * 0.5 * shift, qy - normalY * 0.5 * shift, separation, id)

  /** True when reference vertex r and incident vertex p are the closest points of their sides
    * (whose other ends are rOther and pOther); then the corner point, midway between the two
    * surfaces on the line from r to p (its normal turned by `orientation`), is added if their
    * separation is at most `speculativeDistance`.
    */
  private def cornerPoint(rx: Double, ry: Double, rOtherX: Double, rOtherY: Double, px: Double, py: Double,
      pOtherX: Double, pOtherY: Double, id: Int, orientation: Double, referenceRadius: Double,
      incidentRadius: Double, speculativeDistance: Double,
      manifold: Manifold): Boolean =
    val dx = px - rx
    val dy = py - ry
    val closest = dx *
      (rOtherX - rx) +
      dy *
      (rOtherY - ry) < 0 &&
      dx *
      (pOtherX - px) +
      dy *
      (pOtherY - py) > 0
    if closest then
      val distance = math.sqrt(dx * dx + dy * dy) // > 0: the polygons are apart
      val separation = distance - referenceRadius - incidentRadius
      if separation <= speculativeDistance then
        manifold.normalX = orientation * dx / distance
        manifold.normalY = orientation * dy / distance
        // From r along d to the middle of the surfaces: (distance + rReference - rIncident) / 2.
        val reach = 0.5 * (distance + referenceRadius - incidentRadius) / distance
        manifold.addPoint(rx + dx * reach, ry + dy * reach, separation, id)
    closest
