package sims.collision

import sims.dynamics.{Circle, Shape}
import sims.geometry.{ConvexPolygon, Segment, Vector2D}

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
    val count = polygon.vertexCount
    val cx = circle.x
    val cy = circle.y
    var sideDistance = Double.PositiveInfinity
    var side = 0
    var vertexDistance = Double.PositiveInfinity
    var vertex = 0
    var i = 0
    while i < count do
      val j = if i + 1 == count then 0 else i + 1
      val d = Segment.distance(polygon.vertexX(i), polygon.vertexY(i), polygon.vertexX(j), polygon.vertexY(j), cx, cy)
      if d < sideDistance then { sideDistance = d; side = i }
      val vx = cx - polygon.vertexX(i)
      val vy = cy - polygon.vertexY(i)
      val dv = math.sqrt(vx * vx + vy * vy)
      if dv < vertexDistance then { vertexDistance = dv; vertex = i }
      i += 1
    // Penetrations are distance - r for both, so comparing distances compares penetrations.
    if vertexDistance <= sideDistance && vertexDistance > 0 then
      normalX = (cx - polygon.vertexX(vertex)) / vertexDistance
      normalY = (cy - polygon.vertexY(vertex)) / vertexDistance
    else
      val j = if side + 1 == count then 0 else side + 1
      val dx = polygon.vertexX(j) - polygon.vertexX(side)
      val dy = polygon.vertexY(j) - polygon.vertexY(side)
      val length = math.sqrt(dx * dx + dy * dy)
      normalX = dy / length // right normal of the side: outward for counter-clockwise vertices
      normalY = -dx / length
    pointXs(0) = circle.x - normalX * circle.radius
    pointYs(0) = circle.y - normalY * circle.radius
    pointCount = 1

  def normal: Vector2D = Vector2D(normalX, normalY)
  def points: Iterable[Vector2D] = List(Vector2D(pointXs(0), pointYs(0)))

/** The polygon-circle narrowphase test. */
object PolyCircleCollision:
  /** True when a side is within the radius of the centre, or the polygon contains the centre. */
  def colliding(polygon: ConvexPolygon, circle: Circle): Boolean =
    val count = polygon.vertexCount
    var near = false
    var inside = true
    var i = 0
    while !near && i < count do
      val j = if i + 1 == count then 0 else i + 1
      val ax = polygon.vertexX(i); val ay = polygon.vertexY(i)
      val bx = polygon.vertexX(j); val by = polygon.vertexY(j)
      if Segment.distance(ax, ay, bx, by, circle.x, circle.y) - circle.radius <= 0 then near = true
      if (bx - ax) * (circle.y - ay) - (by - ay) * (circle.x - ax) < 0 then inside = false
      i += 1
    near || inside
