package sims.collision.manifold

import sims.dynamics.{ChainSegment, Circle, RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

// A chain segment's manifold: the edge's, made smooth and one-sided. The segment runs from v1 to
// v2 with unit direction t; its free side's normal is f = (-t.y, t.x). A shape whose centre lies
// behind the segment's line (f . (c - v1) < 0) does not touch it. Otherwise the edge's manifold
// (of the two-sided segment) is kept when its normal n is f, or leans towards an end that is a
// corner of the chain's surface, a convex one, within the corner's cone of normals (between the
// two segments' face normals: the shape meets the corner). Elsewhere the edge's normal belongs
// to no point of the chain's surface: leaning towards a free end is a lone edge's end (kept);
// towards a flat or concave join it is the "ghost" of the segment's corner, which the shape
// sliding over the join would bump against. Then the manifold is measured along f alone: the
// other shape's side facing the segment (or a circle's centre) clipped to the segment's slab,
// the points beyond the join being the neighbour's.
//
// Face points' ids carry FacePoint, so that a pair switching between the two measures does not
// warm start one point from the other's impulse.

/** The manifold of a chain segment against a circle, a polygon, or a capsule or edge. */
private[sims] object ChainSegmentManifold:
  /** Bit set in the ids of points measured along the face normal. */
  val FacePoint: Int = 1 << 29

  /** Fills `manifold` for chain segment A and circle B. */
  def collide(segment: ChainSegment, circle: Circle, speculativeDistance: Double, manifold: Manifold): Unit =
    CapsuleCircleManifold.collide(segment, circle, speculativeDistance, manifold)
    if needsFace(segment, circle, manifold) then faceCircle(segment, circle, speculativeDistance, manifold)

  /** Fills `manifold` for chain segment A and polygon B. */
  def collide(segment: ChainSegment, polygon: Shape & ConvexPolygon, speculativeDistance: Double,
      linearSlop: Double, manifold: Manifold): Unit =
    PolygonManifold.collide(segment, polygon, speculativeDistance, linearSlop, manifold)
    if needsFace(segment, polygon, manifold) then
      face(segment, polygon.vertexXs, polygon.vertexYs, polygon.sideNormalXs, polygon.sideNormalYs, 0,
        speculativeDistance, manifold)

  /** Fills `manifold` for chain segment A and capsule (or edge) B. */
  def collide(segment: ChainSegment, capsule: RoundedSegment, speculativeDistance: Double, linearSlop: Double,
      manifold: Manifold): Unit =
    CapsuleManifold.collide(segment, capsule, speculativeDistance, linearSlop, manifold)
    if needsFace(segment, capsule, manifold) then
      face(segment, capsule.coreXs, capsule.coreYs, capsule.coreNormalXs, capsule.coreNormalYs, capsule.radius,
        speculativeDistance, manifold)

  /** Turns the manifold round, for a pair given the other way (the chain segment second). */
  def flip(manifold: Manifold): Unit = manifold.flipNormal()

  /** Whether the edge's manifold must be measured again along the face normal; clears it when
    * the other shape lies behind the segment.
    */
  private def needsFace(segment: ChainSegment, other: Shape, manifold: Manifold): Boolean =
    if manifold.pointCount == 0 then false
    else
      val xs = segment.coreXs; val ys = segment.coreYs
      val length = 2 * segment.halfLength
      val tx = (xs(1) - xs(0)) / length; val ty = (ys(1) - ys(0)) / length
      val fx = -ty; val fy = tx
      if fx * (other.x - xs(0)) + fy * (other.y - ys(0)) < 0 then
        manifold.clear()
        false
      else
        val nx = manifold.normalX; val ny = manifold.normalY
        val lean = nx * tx + ny * ty
        if lean == 0 then nx * fx + ny * fy <= 0
        else if lean < 0 then
          // Towards v1: the corner with the previous segment, from its start g = v1 + a t + b f.
          if segment.previous.isEmpty then false
          else
            val ex = -segment.previousAlong; val ey = -segment.previousOut // v1 - g in (t, f)
            // The previous segment's direction d0 = (ex, ey) / |e| in (t, f); the corner is
            // convex when the chain turns clockwise from d0 to t: cross(d0, t) < 0, i.e. ey > 0.
            val convex = ey > CornerTolerance * math.sqrt(ex * ex + ey * ey)
            !(convex && withinCone(ex, ey, nx * tx + ny * ty, nx * fx + ny * fy, towardsStart = true))
        else
          if segment.next.isEmpty then false
          else
            val ex = segment.nextAlong; val ey = segment.nextOut // g - v2 in (t, f)
            val convex = ey < -CornerTolerance * math.sqrt(ex * ex + ey * ey)
            !(convex && withinCone(ex, ey, nx * tx + ny * ty, nx * fx + ny * fy, towardsStart = false))

  /** Corners turning by less than this (radians, about) are flat. */
  private val CornerTolerance = 1e-9

  /** Whether the normal (along t, along f) lies between f and the neighbour's face normal, the
    * neighbour's direction being (ex, ey) in (t, f).
    */
  private def withinCone(ex: Double, ey: Double, nt: Double, nf: Double, towardsStart: Boolean): Boolean =
    // The neighbour's face normal: its direction turned left, (-ey, ex) in (t, f).
    val gt = -ey; val gf = ex
    // n lies between f = (0, 1) and g when it is on the same side of each as the other.
    if towardsStart then gt * nf - gf * nt <= 0 && nt <= 0 // g -> n -> f clockwise
    else nt >= 0 && nt * gf - nf * gt <= 0 // f -> n -> g clockwise

  /** The circle against the segment's face alone: nothing when its centre is beyond the slab. */
  private def faceCircle(segment: ChainSegment, circle: Circle, speculativeDistance: Double, manifold: Manifold): Unit =
    manifold.clear()
    val xs = segment.coreXs; val ys = segment.coreYs
    val length = 2 * segment.halfLength
    val tx = (xs(1) - xs(0)) / length; val ty = (ys(1) - ys(0)) / length
    val fx = -ty; val fy = tx
    val u = tx * (circle.x - xs(0)) + ty * (circle.y - ys(0))
    if u >= 0 && u <= length then
      val separation = fx * (circle.x - xs(0)) + fy * (circle.y - ys(0)) - circle.radius
      if separation <= speculativeDistance then
        manifold.normalX = fx
        manifold.normalY = fy
        val back = circle.radius + 0.5 * separation
        manifold.addPoint(circle.x - fx * back, circle.y - fy * back, separation, FacePoint)

  /** The other shape (vertices, outward side normals, radius) against the segment's face alone:
    * its side facing the segment clipped to the segment's slab.
    */
  private def face(segment: ChainSegment, xs: Array[Double], ys: Array[Double], normalXs: Array[Double],
      normalYs: Array[Double], radius: Double, speculativeDistance: Double, manifold: Manifold): Unit =
    manifold.clear()
    val cx = segment.coreXs; val cy = segment.coreYs
    val length = 2 * segment.halfLength
    val tx = (cx(1) - cx(0)) / length; val ty = (cy(1) - cy(0)) / length
    val fx = -ty; val fy = tx
    var side = 0
    var lowest = Double.PositiveInfinity
    var i = 0
    while i < normalXs.length do
      val dot = normalXs(i) * fx + normalYs(i) * fy
      if dot < lowest then
        lowest = dot
        side = i
      i += 1
    val nextVertex = if side + 1 == xs.length then 0 else side + 1
    val p1x = xs(side); val p1y = ys(side)
    val p2x = xs(nextVertex); val p2y = ys(nextVertex)
    val u1 = tx * (p1x - cx(0)) + ty * (p1y - cy(0))
    val u2 = tx * (p2x - cx(0)) + ty * (p2y - cy(0))
    if !((u1 < 0 && u2 < 0) || (u1 > length && u2 > length)) then
      manifold.normalX = fx
      manifold.normalY = fy
      addFacePoint(p1x, p1y, u1, p2x, p2y, u2, cx(0), cy(0), tx, ty, length, radius, side, speculativeDistance, manifold)
      addFacePoint(p2x, p2y, u2, p1x, p1y, u1, cx(0), cy(0), tx, ty, length, radius, nextVertex, speculativeDistance,
        manifold)
      if manifold.pointCount == 0 then manifold.clear()

  /** Vertex p (at u along the segment) of the incident side, moved towards its other end q onto
    * the slab if beyond it, added midway between the surfaces if within the speculative distance.
    */
  private def addFacePoint(px: Double, py: Double, u: Double, qx: Double, qy: Double, uq: Double, v1x: Double,
      v1y: Double, tx: Double, ty: Double, length: Double, radius: Double, id: Int, speculativeDistance: Double,
      manifold: Manifold): Unit =
    val fraction = if u < 0 then -u / (uq - u) else if u > length then (u - length) / (u - uq) else 0.0
    val x = px + (qx - px) * fraction
    val y = py + (qy - py) * fraction
    val fx = -ty; val fy = tx
    val core = fx * (x - v1x) + fy * (y - v1y)
    val separation = core - radius
    if separation <= speculativeDistance then
      val shift = core + radius
      manifold.addPoint(x - fx * 0.5 * shift, y - fy * 0.5 * shift, separation, FacePoint | id)
