package sims.collision

import sims.dynamics.Shape
import sims.geometry.{ConvexPolygon, PolygonMath, Vector2D}

/** Collision of two convex polygons, found with the separating axis theorem. For the pair
  * (first, second) the side normals of the second, then of the first, are tried; the one with
  * the smallest positive overlap of the projections (the first found on ties) gives the normal,
  * and its polygon is the reference; the normal is that side's outward normal, turned round if
  * it faces away from the incident polygon. Points: the incident polygon's vertices inside the
  * reference, then the reference's vertices inside the incident polygon.
  */
final class PolyCollision(first: Shape & ConvexPolygon, second: Shape & ConvexPolygon) extends Collision:
  override private[sims] def solvedInPlace: Boolean = true

  private var reference: Shape & ConvexPolygon = first
  private var incident: Shape & ConvexPolygon = second
  compute(first, second)

  def shape1: Shape & ConvexPolygon = reference
  def shape2: Shape & ConvexPolygon = incident

  /** Recomputes this collision for the pair (first, second) from their current positions. */
  private[collision] def compute(first: Shape & ConvexPolygon, second: Shape & ConvexPolygon): Unit =
    compute(first, second, PolyCollision.referenceAxis(first, second))

  /** `compute` with the reference axis already found (by `referenceAxisIfColliding`). */
  private[collision] def compute(first: Shape & ConvexPolygon, second: Shape & ConvexPolygon, axis: Int): Unit =
    val secondIsReference = axis < second.vertexCount
    reference = if secondIsReference then second else first
    incident = if secondIsReference then first else second
    // The overlap of two intervals does not depend on the axis' sign, so parallel opposite
    // sides (a box's top and bottom) tie and the side found first may face away from the
    // incident polygon. The normal is therefore oriented from the reference towards the
    // incident polygon (see the deviations: the original hid this by reporting every pair in
    // both orders).
    val side = PolyCollision.sideOf(axis, second)
    val nx = reference.sideNormalXs(side)
    val ny = reference.sideNormalYs(side)
    val refXs = reference.vertexXs
    val refYs = reference.vertexYs
    val incXs = incident.vertexXs
    val incYs = incident.vertexYs
    val facing = PolyCollision.facing(refXs, refYs, incXs, incYs, nx, ny)
    normalX = facing * nx
    normalY = facing * ny
    ensureCapacity(first.vertexCount + second.vertexCount)
    pointCount = 0
    collect(incXs, incYs, refXs, refYs)
    collect(refXs, refYs, incXs, incYs)

  /** Appends the vertices of one polygon that lie inside the other to the points. */
  private def collect(fromXs: Array[Double], fromYs: Array[Double], insideXs: Array[Double], insideYs: Array[Double]): Unit =
    var i = 0
    while i < fromXs.length do
      if PolygonMath.contains(insideXs, insideYs, insideXs.length, fromXs(i), fromYs(i)) then
        pointXs(pointCount) = fromXs(i)
        pointYs(pointCount) = fromYs(i)
        pointCount += 1
      i += 1

  def normal: Vector2D = Vector2D(normalX, normalY)
  def points: Iterable[Vector2D] = pointVectors

/** The polygon-polygon narrowphase (separating axis theorem). */
object PolyCollision:
  /** True when the projections of the polygons overlap (or touch) on every side normal of both. */
  def colliding(p1: ConvexPolygon, p2: ConvexPolygon): Boolean =
    separatingAxisTest(p1, p2, stopWhenSeparated = true) >= 0

  /** Index of the reference axis: `k < second.vertexCount` is side k of the second polygon,
    * otherwise side `k - second.vertexCount` of the first.
    */
  private def referenceAxis(first: ConvexPolygon, second: ConvexPolygon): Int =
    separatingAxisTest(first, second, stopWhenSeparated = false)

  /** `colliding(first, second)` and `referenceAxis(first, second)` in one pass: -1 when some
    * axis separates the polygons (the first one `colliding` would stop at), else the reference
    * axis.
    */
  private[collision] def referenceAxisIfColliding(first: ConvexPolygon, second: ConvexPolygon): Int =
    separatingAxisTest(first, second, stopWhenSeparated = true)

  /** The SAT over the second polygon's side normals, then the first's: the axis with the
    * smallest positive projection overlap (the first found on ties; axis 0 when none is
    * positive, as for polygons that only touch). With `stopWhenSeparated`, -1 as soon as an
    * axis separates the polygons.
    */
  private def separatingAxisTest(first: ConvexPolygon, second: ConvexPolygon, stopWhenSeparated: Boolean): Int =
    val firstXs = first.vertexXs; val firstYs = first.vertexYs
    val secondXs = second.vertexXs; val secondYs = second.vertexYs
    val firstNxs = first.sideNormalXs; val firstNys = first.sideNormalYs
    val secondNxs = second.sideNormalXs; val secondNys = second.sideNormalYs
    val count2 = secondXs.length
    val total = count2 + firstXs.length
    var best = -1
    var bestOverlap = Double.PositiveInfinity
    var separated = false
    var k = 0
    while !separated && k < total do
      val nx = if k < count2 then secondNxs(k) else firstNxs(k - count2)
      val ny = if k < count2 then secondNys(k) else firstNys(k - count2)
      val lower1 = PolygonMath.projectionMin(firstXs, firstYs, firstXs.length, nx, ny)
      val upper1 = PolygonMath.projectionMax(firstXs, firstYs, firstXs.length, nx, ny)
      val lower2 = PolygonMath.projectionMin(secondXs, secondYs, count2, nx, ny)
      val upper2 = PolygonMath.projectionMax(secondXs, secondYs, count2, nx, ny)
      if stopWhenSeparated && (upper1 < lower2 || upper2 < lower1) then separated = true
      else
        val overlap = sims.geometry.Projection.overlap(lower1, upper1, lower2, upper2)
        if overlap > 0 && overlap < bestOverlap then
          best = k
          bestOverlap = overlap
      k += 1
    if separated then -1 else if best < 0 then 0 else best

  /** 1 if (nx, ny) points from the reference's vertex centroid towards the incident's, else -1. */
  private def facing(refXs: Array[Double], refYs: Array[Double], incXs: Array[Double], incYs: Array[Double],
      nx: Double, ny: Double): Double =
    val dx = mean(incXs) - mean(refXs)
    val dy = mean(incYs) - mean(refYs)
    if nx * dx + ny * dy < 0 then -1.0 else 1.0

  /** Mean of the coordinates, summed in order: a vertex centroid's coordinate. */
  private def mean(values: Array[Double]): Double =
    var sum = 0.0
    var i = 0
    while i < values.length do { sum += values(i); i += 1 }
    sum / values.length

  private def sideOf(k: Int, second: ConvexPolygon): Int =
    if k < second.vertexCount then k else k - second.vertexCount
