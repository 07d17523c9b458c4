package sims.collision.manifold

import sims.dynamics.{Circle, Shape}
import sims.geometry.{ConvexPolygon, PolygonMath}

// Polygon-circle manifold. Side i (from vertex v_i to v_i+1, outward unit normal n_i) is
// d_i = n_i . (c - v_i) away from the centre c. The side of greatest d_i is the one the
// circle lies most beyond; its separation is d_i - r, and the point lies midway between the
// side's line (at c - n_i d_i) and the circle's surface (at c - n_i r).
//
// Outside the polygon (d_i > 0) the centre may project beyond an end of that side, into a
// vertex region: then the vertex v is the nearest feature, the normal runs from v to c and
// the separation is |c - v| - r.
//
// Inside the polygon (every d_i < 0) the greatest d_i is the nearest side, which jumps to the
// far side once a ball is pushed past the middle of a thick floor, and the ball is then
// thrown out through the floor's bottom (docs/performance.md, ball pits). So a centre inside
// keeps the side used in the last step unless another side is nearer by more than the radius.

/** The manifold of a convex polygon and a circle (see docs/two-solvers.md). */
private[sims] object PolygonCircleManifold:

  /** Fills `manifold` for polygon A and circle B: at most one point, midway between the
    * surfaces, when the separation is at most `speculativeDistance`. Its id is the side index
    * i for a side contact, `vertexCount + j` for a contact with vertex j. `lastSide` is
    * `manifold.polygonSide` of the last step (-1 if none): a centre inside the polygon keeps
    * that side unless another side separates better by more than the radius.
    */
  def collide(polygon: Shape & ConvexPolygon, circle: Circle, lastSide: Int, speculativeDistance: Double,
      manifold: Manifold): Unit =
    manifold.clear()
    val count = polygon.vertexCount
    val vertexXs = polygon.vertexXs
    val vertexYs = polygon.vertexYs
    val normalXs = polygon.sideNormalXs
    val normalYs = polygon.sideNormalYs
    val centreX = circle.x
    val centreY = circle.y
    val radius = circle.radius

    var side = PolygonMath.farthestSide(vertexXs, vertexYs, normalXs, normalYs, count, centreX, centreY)
    var sideDistance = PolygonMath.sideDistance(vertexXs, vertexYs, normalXs, normalYs, side, centreX, centreY)

    if sideDistance < 0 && lastSide >= 0 && lastSide < count && lastSide != side then
      val lastDistance = PolygonMath.sideDistance(vertexXs, vertexYs, normalXs, normalYs, lastSide, centreX, centreY)
      if sideDistance - lastDistance <= radius then
        side = lastSide
        sideDistance = lastDistance

    if sideDistance - radius <= speculativeDistance then
      val next = if side + 1 == count then 0 else side + 1
      val startX = vertexXs(side); val startY = vertexYs(side)
      val endX = vertexXs(next); val endY = vertexYs(next)
      // Where the centre projects along the side, measured from each end towards the other.
      val beyondStart = (centreX - startX) * (endX - startX) + (centreY - startY) * (endY - startY) < 0
      val beyondEnd = (centreX - endX) * (startX - endX) + (centreY - endY) * (startY - endY) < 0
      if sideDistance > 0 && beyondStart then
        vertexContact(startX, startY, side, count + side, centreX, centreY, radius, speculativeDistance, manifold)
      else if sideDistance > 0 && beyondEnd then
        vertexContact(endX, endY, side, count + next, centreX, centreY, radius, speculativeDistance, manifold)
      else
        val normalX = normalXs(side)
        val normalY = normalYs(side)
        val reach = 0.5 * (sideDistance + radius) // from the centre back to the point
        manifold.normalX = normalX
        manifold.normalY = normalY
        manifold.polygonSide = side
        manifold.addPoint(centreX - normalX * reach, centreY - normalY * reach, sideDistance - radius, side)

  /** `collide` for circle A and polygon B: the same point, separation and id, the normal
    * turned round so that it still points from A (the circle) to B (the polygon).
    */
  def collide(circle: Circle, polygon: Shape & ConvexPolygon, lastSide: Int, speculativeDistance: Double,
      manifold: Manifold): Unit =
    collide(polygon, circle, lastSide, speculativeDistance, manifold)
    manifold.flipNormal()

  /** The contact of the circle with the polygon's vertex (vertexX, vertexY), if within
    * `speculativeDistance`: normal from the vertex to the centre, separation |c - v| - r.
    */
  private def vertexContact(vertexX: Double, vertexY: Double, side: Int, id: Int, centreX: Double,
      centreY: Double, radius: Double, speculativeDistance: Double, manifold: Manifold): Unit =
    val dx = centreX - vertexX
    val dy = centreY - vertexY
    val distance = math.sqrt(dx * dx + dy * dy) // > 0: the centre is outside the polygon
    val separation = distance - radius
    if separation <= speculativeDistance then
      val normalX = dx / distance
      val normalY = dy / distance
      manifold.normalX = normalX
      manifold.normalY = normalY
      manifold.polygonSide = side
      manifold.addPoint(vertexX + normalX * 0.5 * separation, vertexY + normalY * 0.5 * separation, separation, id)
