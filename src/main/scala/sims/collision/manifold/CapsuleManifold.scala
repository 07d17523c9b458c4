package sims.collision.manifold

import sims.dynamics.RoundedSegment

// Capsule-capsule manifold (an edge is a capsule of radius 0). Each capsule is the set of
// points within its radius r of its core segment, so the two are apart by the distance of
// their cores less rA + rB.
//
// Closest points. With cores p(s) = p1 + s d1 and q(t) = q1 + t d2, s and t in [0, 1], the
// squared distance |p(s) - q(t)|^2 is convex in (s, t). Its unconstrained minimum along s for
// the best t, clamped to [0, 1], then the best t for that s, clamped, and s again for a
// clamped t, is the constrained minimum (Ericson, Real-Time Collision Detection, 5.1.9).
// Parallel cores (d1 x d2 = 0) have no single minimum; then s = 0 starts the search.
//
// One point: midway between the surfaces on the line of the closest points cA, cB, normal
// n = (cB - cA) / |cB - cA|, separation |cB - cA| - rA - rB. Cores that cross have no such
// line (it turns with every rounding): then the side normal of the core that separates them
// better, as between polygons, pointing towards the other core's middle, and separation
// -rA - rB (two crossing edges touch).
//
// Two points: a capsule lying along another (cores parallel within ParallelSine) rests on a
// stretch of it, which one point would let rock. As in the polygon manifold, the reference is
// the core whose side normal separates better (A's unless B's is better by more than
// 0.1 linearSlop); the incident core is clipped to the reference core's slab (the points whose
// projection falls between its ends), and each end q of what remains gives a point midway
// between the surfaces along the reference normal n: core separation c = n . (q - r1), point
// q - n (c + rIncident - rReference) / 2, separation c - rA - rB. Points beyond the speculative
// distance are dropped; if none is left, or the cores do not overlap along their length, the
// one point is made instead, so a pair within the speculative distance always has a point.

/** The manifold of two capsules (or edges, or one of each). */
private[sims] object CapsuleManifold:

  /** Cores this close to parallel (the sine of their angle) may lie along each other. */
  val ParallelSine: Double = 0.05

  /** Cores closer than this share of their lengths count as crossing. */
  private val CrossingTolerance = 1e-12

  /** The id of a one-point manifold is `3 featureA + featureB`, each feature the core's first
    * end (0), second end (1) or a point between them (2).
    */
  private val Between = 2

  /** Bit of the ids of the two-point manifold (whose low bit is the incident end's index). */
  val TwoPoints: Int = 16

  /** Bit set in a two-point id when B gave the reference core. */
  val ReferenceIsB: Int = 8

  /** Fills `manifold` for capsules A and B (see the comment above for the ids). */
  def collide(capsuleA: RoundedSegment, capsuleB: RoundedSegment, speculativeDistance: Double, linearSlop: Double,
      manifold: Manifold): Unit =
    manifold.clear()
    val aXs = capsuleA.coreXs; val aYs = capsuleA.coreYs
    val bXs = capsuleB.coreXs; val bYs = capsuleB.coreYs
    val d1x = aXs(1) - aXs(0); val d1y = aYs(1) - aYs(0)
    val d2x = bXs(1) - bXs(0); val d2y = bYs(1) - bYs(0)
    val rx = aXs(0) - bXs(0); val ry = aYs(0) - bYs(0)
    val a = d1x * d1x + d1y * d1y // > 0: cores have a length
    val e = d2x * d2x + d2y * d2y
    val f = d2x * rx + d2y * ry
    val c = d1x * rx + d1y * ry
    val b = d1x * d2x + d1y * d2y
    val denominator = a * e - b * b
    var s = if denominator > 0 then clamp((b * f - c * e) / denominator) else 0.0
    var t = (b * s + f) / e
    if t < 0 then
      t = 0
      s = clamp(-c / a)
    else if t > 1 then
      t = 1
      s = clamp((b - c) / a)
    val closestAX = aXs(0) + s * d1x; val closestAY = aYs(0) + s * d1y
    val closestBX = bXs(0) + t * d2x; val closestBY = bYs(0) + t * d2y
    val gapX = closestBX - closestAX; val gapY = closestBY - closestAY
    // Cores that meet have closest points in no particular direction: within rounding of
    // their lengths, they count as crossing, at distance 0. (What rounding leaves of the
    // distance would otherwise decide whether two crossing edges, of radius 0, touch.)
    val gapLength = math.sqrt(gapX * gapX + gapY * gapY)
    val crossing = gapLength <= CrossingTolerance * (math.sqrt(a) + math.sqrt(e))
    val distance = if crossing then 0.0 else gapLength
    val radiusA = capsuleA.radius
    val radiusB = capsuleB.radius
    if distance - radiusA - radiusB <= speculativeDistance then
      val cross = d1x * d2y - d1y * d2x
      if !crossing && math.abs(cross) <= ParallelSine * math.sqrt(a * e) then
        alongEachOther(capsuleA, capsuleB, gapX, gapY, speculativeDistance, linearSlop, manifold)
      if manifold.pointCount == 0 then
        var normalX = 0.0
        var normalY = 0.0
        if !crossing then
          normalX = gapX / distance
          normalY = gapY / distance
        else
          // The side normal, of either core, that separates them better (A's on a near tie).
          val sideA = towards(capsuleA, capsuleB, 0, 0)
          val sideB = towards(capsuleB, capsuleA, 0, 0)
          if coreSeparation(capsuleB, sideB, capsuleA) > coreSeparation(capsuleA, sideA, capsuleB) + 0.1 * linearSlop then
            normalX = -capsuleB.coreNormalXs(sideB)
            normalY = -capsuleB.coreNormalYs(sideB)
          else
            normalX = capsuleA.coreNormalXs(sideA)
            normalY = capsuleA.coreNormalYs(sideA)
        val separation = distance - radiusA - radiusB
        val reach = radiusA + 0.5 * separation
        manifold.normalX = normalX
        manifold.normalY = normalY
        manifold.addPoint(closestAX + normalX * reach, closestAY + normalY * reach, separation,
          3 * feature(s) + feature(t))

  /** The two-point manifold of cores that lie nearly parallel without meeting, if they overlap
    * along their length; (gapX, gapY) from A's closest point to B's.
    */
  private def alongEachOther(capsuleA: RoundedSegment, capsuleB: RoundedSegment, gapX: Double, gapY: Double,
      speculativeDistance: Double, linearSlop: Double, manifold: Manifold): Unit =
    val sideA = towards(capsuleA, capsuleB, gapX, gapY)
    val sideB = towards(capsuleB, capsuleA, -gapX, -gapY)
    val separationA = coreSeparation(capsuleA, sideA, capsuleB)
    val separationB = coreSeparation(capsuleB, sideB, capsuleA)
    if separationB > separationA + 0.1 * linearSlop then
      clip(capsuleB, sideB, capsuleA, referenceIsB = true, speculativeDistance, manifold)
    else clip(capsuleA, sideA, capsuleB, referenceIsB = false, speculativeDistance, manifold)

  /** The side (0 or 1) of `capsule`'s core whose normal points towards `other`: along
    * (towardsX, towardsY) when that is not null, else towards the other core's middle.
    */
  private def towards(capsule: RoundedSegment, other: RoundedSegment, towardsX: Double, towardsY: Double): Int =
    val normalX = capsule.coreNormalXs(0)
    val normalY = capsule.coreNormalYs(0)
    val along =
      if towardsX != 0 || towardsY != 0 then normalX * towardsX + normalY * towardsY
      else
        normalX * (other.coreXs(0) + other.coreXs(1) - capsule.coreXs(0) - capsule.coreXs(1)) +
          normalY * (other.coreYs(0) + other.coreYs(1) - capsule.coreYs(0) - capsule.coreYs(1))
    if along >= 0 then 0 else 1

  /** How far the other core lies beyond `capsule`'s core along the normal of `side`: the
    * lesser of its two ends'.
    */
  private def coreSeparation(capsule: RoundedSegment, side: Int, other: RoundedSegment): Double =
    val normalX = capsule.coreNormalXs(side)
    val normalY = capsule.coreNormalYs(side)
    val x0 = capsule.coreXs(0)
    val y0 = capsule.coreYs(0)
    math.min(normalX * (other.coreXs(0) - x0) + normalY * (other.coreYs(0) - y0),
      normalX * (other.coreXs(1) - x0) + normalY * (other.coreYs(1) - y0))

  /** The incident core clipped to the reference core's slab: up to two points (none if the
    * cores do not overlap along their length).
    */
  private def clip(reference: RoundedSegment, side: Int, incident: RoundedSegment, referenceIsB: Boolean,
      speculativeDistance: Double, manifold: Manifold): Unit =
    val r1x = reference.coreXs(0); val r1y = reference.coreYs(0)
    val tx = reference.coreXs(1) - r1x; val ty = reference.coreYs(1) - r1y
    val length2 = tx * tx + ty * ty
    // Positions of the incident ends along the reference core, 0 at its first end, 1 at its second.
    val u0 = (tx * (incident.coreXs(0) - r1x) + ty * (incident.coreYs(0) - r1y)) / length2
    val u1 = (tx * (incident.coreXs(1) - r1x) + ty * (incident.coreYs(1) - r1y)) / length2
    if math.max(u0, u1) >= 0 && math.min(u0, u1) <= 1 then
      val normalX = reference.coreNormalXs(side)
      val normalY = reference.coreNormalYs(side)
      val orientation = if referenceIsB then -1.0 else 1.0
      manifold.normalX = orientation * normalX
      manifold.normalY = orientation * normalY
      val idBase = TwoPoints | (if referenceIsB then ReferenceIsB else 0)
      var end = 0
      while end < 2 do
        val u = if end == 0 then u0 else u1
        val otherU = if end == 0 then u1 else u0
        // Moved along the incident core to the nearer end of the slab if it lies outside.
        val limit = if u < 0 then 0.0 else if u > 1 then 1.0 else u
        val k = if u == limit then 0.0 else (limit - u) / (otherU - u)
        val qx = incident.coreXs(end) + k * (incident.coreXs(1 - end) - incident.coreXs(end))
        val qy = incident.coreYs(end) + k * (incident.coreYs(1 - end) - incident.coreYs(end))
        val core = normalX * (qx - r1x) + normalY * (qy - r1y)
        val separation = core - reference.radius - incident.radius
        if separation <= speculativeDistance then
          val shift = core + incident.radius - reference.radius // twice q's distance to the middle
          manifold.addPoint(qx - normalX * 0.5 * shift, qy - normalY * 0.5 * shift, separation, idBase | end)
        end += 1
      if manifold.pointCount == 0 then manifold.clear()

  private inline def clamp(value: Double): Double = if value < 0 then 0.0 else if value > 1 then 1.0 else value

  /** The feature of a core at parameter u: its first end, its second end, or between. */
  private inline def feature(u: Double): Int = if u == 0 then 0 else if u == 1 then 1 else Between
