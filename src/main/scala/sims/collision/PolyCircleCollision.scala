package sims.collision

import sims.dynamics.{Circle, Shape}
import sims.geometry.{ConvexPolygon, PolygonMath, Reach, Segment, Vector2D}

/** Collision of a convex polygon (the reference) and a circle. The normal is the outward normal
  * of the side the circle penetrates deepest, `(distance to side) - r`, unless a vertex
  * penetrates at least as deeply: then it is the unit vector from that vertex to the centre.
  * One point: `centre - n r`, on the polygon's outline when the shapes just touch.
  */
final class PolyCircleCollision(polygon: Shape & ConvexPolygon, circle: Circle) extends Collision:
  private var reference: Shape & ConvexPolygon = polygon
  private var incident: Circle = circle
  override private[sims] def solvedInPlace: Boolean = true
  ensureCapacity(1)
  compute(polygon, circle)

  def shape1: Shape & ConvexPolygon = reference
  def shape2: Circle = incident

  /** Recomputes this collision for the polygon and the circle from their current positions. */
  private[collision] def compute(polygon: Shape & ConvexPolygon, circle: Circle): Unit =
    reference = polygon
    incident = circle
    val xs = polygon.vertexXs
    val ys = polygon.vertexYs
    val count = xs.length
    val cx = circle.x
    val cy = circle.y
    var sideDistance = Double.PositiveInfinity
    var side = 0
    var vertexDistance = Double.PositiveInfinity
    var vertex = 0
    var i = 0
    while i < count do
      val j = PolygonMath.next(i, count)
      val d = Segment.distance(xs(i), ys(i), xs(j), ys(j), cx, cy)
      if d < sideDistance then { sideDistance = d; side = i }
      val vx = cx - xs(i)
      val vy = cy - ys(i)
      val dv = math.sqrt(vx * vx + vy * vy)
      if dv < vertexDistance then { vertexDistance = dv; vertex = i }
      i += 1
    // Penetrations are distance - r for both, so comparing distances compares penetrations.
    if vertexDistance <= sideDistance && vertexDistance > 0 then
      normalX = (cx - xs(vertex)) / vertexDistance
      normalY = (cy - ys(vertex)) / vertexDistance
    else
      normalX = PolygonMath.sideNormalX(xs, ys, count, side)
      normalY = PolygonMath.sideNormalY(xs, ys, count, side)
    pointXs(0) = circle.x - normalX * circle.radius
    pointYs(0) = circle.y - normalY * circle.radius
    pointCount = 1

  def normal: Vector2D = Vector2D(normalX, normalY)
  def points: Iterable[Vector2D] = List(Vector2D(pointXs(0), pointYs(0)))

/** The polygon-circle narrowphase test. */
object PolyCircleCollision:
  /** True when a side is within the radius of the centre, or the polygon contains the centre. */
  def colliding(polygon: ConvexPolygon, circle: Circle): Boolean =
    val xs = polygon.vertexXs
    val ys = polygon.vertexYs
    val count = xs.length
    var near = false
    var i = 0
    while !near && i < count do
      val j = PolygonMath.next(i, count)
      if Reach.within(Segment.squaredDistance(xs(i), ys(i), xs(j), ys(j), circle.x, circle.y), circle.radius) then near = true
      i += 1
    near || PolygonMath.contains(xs, ys, count, circle.x, circle.y)
