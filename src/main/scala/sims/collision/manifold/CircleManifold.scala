package sims.collision.manifold

import sims.dynamics.Circle

// Circle-circle manifold. With d the distance of the centres and n = (cB - cA) / d, the
// surfaces face each other along the line of centres: A's at cA + rA n, B's at cB - rB n.
// Their gap along n is the separation s = d - rA - rB, and the single point lies midway
// between them: cA + n (rA + s / 2). Coincident centres have no line of centres; any fixed
// normal is as good as another there, and (0, 1) keeps the result deterministic.

/** The manifold of two circles (SOFTSTEP.md section 4). */
private[sims] object CircleManifold:

  /** Fills `manifold` for circles A and B: one point with id 0 when their separation
    * `d - rA - rB` is at most `speculativeDistance`, else no point.
    */
  def collide(circleA: Circle, circleB: Circle, speculativeDistance: Double, manifold: Manifold): Unit =
    manifold.clear()
    val dx = circleB.x - circleA.x
    val dy = circleB.y - circleA.y
    val distance = math.sqrt(dx * dx + dy * dy)
    val separation = distance - circleA.radius - circleB.radius
    if separation <= speculativeDistance then
      val normalX = if distance == 0 then 0.0 else dx / distance
      val normalY = if distance == 0 then 1.0 else dy / distance
      val reach = circleA.radius + 0.5 * separation // from A's centre to the point
      manifold.normalX = normalX
      manifold.normalY = normalY
      manifold.addPoint(circleA.x + normalX * reach, circleA.y + normalY * reach, separation, 0)
