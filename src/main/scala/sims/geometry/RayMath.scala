package sims.geometry

/** Ray casts against the built-in outlines, allocation-free, for the world's queries and the
  * shapes' `rayCast`. A ray here is the segment p(t) = (x1, y1) + t (dx, dy), t from 0 to
  * `maxFraction` (at most 1: the ray's end); a cast reports where the ray first enters the
  * outline: the fraction t and the outline's outward unit normal there, written into a [[RayMath.Hit]].
  * A ray that starts inside a shape does not hit it (it never enters it): Box2D's rule too.
  */
private[sims] object RayMath:
  /** Where a cast hit: the fraction of the ray and the unit normal, filled by the casts. */
  final class Hit:
    /** Fraction of the ray, 0 at its start. */
    var fraction: Double = 0
    /** x of the outline's unit normal at the hit. */
    var normalX: Double = 0
    /** y of the outline's unit normal at the hit. */
    var normalY: Double = 0

    /** Records a hit at `t` with normal (nx, ny); true, for the casts to return. */
    private[RayMath] def set(t: Double, nx: Double, ny: Double): Boolean =
      fraction = t
      normalX = nx
      normalY = ny
      true

  /** The circle of centre (cx, cy) and `radius`: where the ray enters it, if it does so within
    * [0, maxFraction] (a start inside enters behind the start: a miss).
    *
    * Measured from the line's closest point to the centre, as Box2D does: with u the ray's unit
    * direction and q the closest point, the ray enters |q - c| ^ 2 + h ^ 2 = r ^ 2 a distance h
    * before q. The textbook root of |p(t) - c| = r, from b^2 - ac with both terms measured from
    * the ray's start, loses digits with the square of the ray's length: a 2e8 m ray across a
    * 0.24 m circle put its hit inside the disc.
    */
  def circle(cx: Double, cy: Double, radius: Double, x1: Double, y1: Double, dx: Double, dy: Double,
      maxFraction: Double, hit: Hit): Boolean =
    val length = math.sqrt(dx * dx + dy * dy)
    if length == 0 then false
    else
      val ux = dx / length
      val uy = dy / length
      // The start and the line's closest point, from the centre.
      val sx = x1 - cx
      val sy = y1 - cy
      val closest = -(sx * ux + sy * uy) // how far along the line from the start
      val qx = sx + closest * ux
      val qy = sy + closest * uy
      val squared = qx * qx + qy * qy
      val rr = radius * radius
      if squared > rr then false
      else
        val enter = closest - math.sqrt(rr - squared) // distance along the line from the start
        val t = enter / length
        if t < 0 || t > maxFraction then false
        else
          val px = sx + enter * ux
          val py = sy + enter * uy
          val normalLength = math.sqrt(px * px + py * py)
          if normalLength == 0 then false else hit.set(t, px / normalLength, py / normalLength)

  /** A convex polygon (vertices counter-clockwise, outward unit side normals): the ray clipped to
    * each side's half plane (Cyrus-Beck); it enters where the last side it comes in through
    * is crossed, if it is inside all of them before `maxFraction`.
    */
  def polygon(xs: Array[Double], ys: Array[Double], normalXs: Array[Double], normalYs: Array[Double], count: Int,
      x1: Double, y1: Double, dx: Double, dy: Double, maxFraction: Double, hit: Hit): Boolean =
    var lower = 0.0
    var upper = maxFraction
    var entering = -1
    var i = 0
    var open = true
    while open && i < count do
      // Inside side i's half plane where n . (p(t) - v_i) <= 0: numerator >= denominator t.
      val numerator = normalXs(i) * (xs(i) - x1) + normalYs(i) * (ys(i) - y1)
      val denominator = normalXs(i) * dx + normalYs(i) * dy
      if denominator == 0 then
        if numerator < 0 then open = false // parallel, outside
      else if denominator < 0 then
        if numerator <= lower * denominator then // enters later than `lower`
          lower = numerator / denominator
          entering = i
      else if numerator < upper * denominator then upper = numerator / denominator // leaves sooner
      if upper < lower then open = false
      i += 1
    if !open || entering < 0 then false // missed, or started inside
    else hit.set(lower, normalXs(entering), normalYs(entering))

  /** One side of a segment from (ax, ay) to (bx, by) whose outward unit normal is (nx, ny): hit
    * only when the ray comes in against the normal.
    */
  private def side(ax: Double, ay: Double, bx: Double, by: Double, nx: Double, ny: Double, x1: Double, y1: Double,
      dx: Double, dy: Double, maxFraction: Double, hit: Hit): Boolean =
    val denominator = nx * dx + ny * dy
    if denominator >= 0 then false
    else
      val t = (nx * (ax - x1) + ny * (ay - y1)) / denominator
      if t < 0 || t > maxFraction then false
      else
        val ex = bx - ax
        val ey = by - ay
        val along =
          ((x1 + t * dx - ax) * ex + (y1 + t * dy - ay) * ey) /
            (ex * ex + ey * ey)
        if along < 0 || along > 1 then false else hit.set(t, nx, ny)

  /** A segment from (ax, ay) to (bx, by) (not a point), hit from either side; the normal faces the
    * ray's start. A ray along the segment's line misses it.
    */
  def segment(ax: Double, ay: Double, bx: Double, by: Double, x1: Double, y1: Double, dx: Double, dy: Double,
      maxFraction: Double, hit: Hit): Boolean =
    val length = math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay))
    val nx = (by - ay) / length
    val ny = -(bx - ax) / length
    side(ax, ay, bx, by, nx, ny, x1, y1, dx, dy, maxFraction, hit) ||
    side(ax, ay, bx, by, -nx, -ny, x1, y1, dx, dy, maxFraction, hit)

  /** The points within `radius` of the segment (ax, ay) - (bx, by): a rectangle along it and a
    * disc at each end. From outside, the ray first enters the union where it first enters one
    * of them; the rectangle's ends lie inside the discs, so only its two long sides count.
    * Radius 0 is the segment itself.
    */
  def capsule(ax: Double, ay: Double, bx: Double, by: Double, radius: Double, x1: Double, y1: Double, dx: Double,
      dy: Double, maxFraction: Double, hit: Hit): Boolean =
    if radius == 0 then segment(ax, ay, bx, by, x1, y1, dx, dy, maxFraction, hit)
    else if Segment.distance(ax, ay, bx, by, x1, y1) < radius then false // starts inside
    else
      val length = math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay))
      val nx = (by - ay) / length
      val ny = -(bx - ax) / length
      var limit = maxFraction
      var found = false
      // Each cast below only hits nearer than `limit`, which each hit lowers.
      if circle(ax, ay, radius, x1, y1, dx, dy, limit, hit) then { found = true; limit = hit.fraction }
      if circle(bx, by, radius, x1, y1, dx, dy, limit, hit) then { found = true; limit = hit.fraction }
      if side(ax + radius * nx, ay + radius * ny, bx + radius * nx, by + radius * ny, nx, ny, x1, y1, dx, dy, limit, hit)
      then { found = true; limit = hit.fraction }
      if side(ax - radius * nx, ay - radius * ny, bx - radius * nx, by - radius * ny, -nx, -ny, x1, y1, dx, dy, limit, hit)
      then found = true
      found
