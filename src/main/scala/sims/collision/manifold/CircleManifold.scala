package sims.collision.manifold

import sims.dynamics.Circle

// Circle-circle manifold. With d the distance of the centres and n = (cB - cA) / d, the
// surfaces face each other along the line of centres: A's at cA + rA n, B's at cB - rB n.
// Their gap along n is the separation s = d - rA - rB, and the single point lies midway
// between them: cA + n (rA + s / 2). Coincident centres have no line of centres; any fixed
// normal is as good as another there, and (0, 1) keeps the result deterministic.

/** The manifold of two circles (see docs/two-solvers.md). */
private[sims] object CircleManifold:

  /** Fills `manifold` for circles A and B: one point with id 0 when their separation
    * `d - rA - rB` is at most `speculativeDistance`, else no point.
    */
  def collide(circleA: Circle, circleB: Circle, speculativeDistance: Double, manifold: Manifold): Unit =
    discs(circleA.x, circleA.y, circleA.radius, circleB.x, circleB.y, circleB.radius, speculativeDistance, manifold)

  /** `collide` for discs of centres (aX, aY), (bX, bY) and radii: also the capsule-circle case,
    * whose capsule acts as a disc centred on its core's point nearest the circle.
    */
  private[manifold] def discs(aX: Double, aY: Double, radiusA: Double, bX: Double, bY: Double, radiusB: Double,
      speculativeDistance: Double, manifold: Manifold): Unit =
    manifold.clear()
    val dx = bX - aX
    val dy = bY - aY
    val distance = math.sqrt(dx * dx + dy * dy)
    val separation = distance - radiusA - radiusB
    if separation <= speculativeDistance then
      val normalX = if distance == 0 then 0.0 else dx / distance
      val normalY = if distance == 0 then 1.0 else dy / distance
      val reach = radiusA + 0.5 * separation // from A's centre to the point
      manifold.normalX = normalX
      manifold.normalY = normalY
      manifold.addPoint(aX + normalX * reach, aY + normalY * reach, separation, 0)
