package sims.collision.manifold

import sims.dynamics.{Circle, RoundedSegment}

// Capsule-circle manifold. A capsule is the set of points within its radius of its core
// segment p1 -> p2, so its distance to a circle of centre c is that of the core's nearest
// point q = p1 + t (p2 - p1), t = ((c - p1) . (p2 - p1)) / |p2 - p1|^2 clamped to [0, 1],
// less the two radii. Around q the capsule is a disc of its radius: the manifold is the
// circle-circle one of that disc and the circle (an edge is the case of radius 0).

/** The manifold of a capsule or an edge and a circle. */
private[sims] object CapsuleCircleManifold:

  /** Fills `manifold` for capsule (or edge) A and circle B: one point with id 0, midway between
    * the surfaces on the line from the core's nearest point to the centre, when the separation
    * is at most `speculativeDistance`.
    */
  def collide(capsule: RoundedSegment, circle: Circle, speculativeDistance: Double, manifold: Manifold): Unit =
    val xs = capsule.coreXs
    val ys = capsule.coreYs
    val ex = xs(1) - xs(0)
    val ey = ys(1) - ys(0)
    val along = ((circle.x - xs(0)) * ex + (circle.y - ys(0)) * ey) / (ex * ex + ey * ey)
    val t = math.max(0.0, math.min(1.0, along))
    CircleManifold.discs(xs(0) + t * ex, ys(0) + t * ey, capsule.radius, circle.x, circle.y, circle.radius,
      speculativeDistance, manifold)

  /** `collide` for circle A and capsule B: the same point, the normal turned round. */
  def collide(circle: Circle, capsule: RoundedSegment, speculativeDistance: Double, manifold: Manifold): Unit =
    collide(capsule, circle, speculativeDistance, manifold)
    manifold.flipNormal()
