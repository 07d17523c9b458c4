package sims.geometry

/** A half line starting at `point` and going in `direction` (not null). */
final case class Ray(point: Vector2D, direction: Vector2D):
  require(!direction.isNull, "Ray direction must not be the null vector")

  /** True if this ray crosses or touches `segment`. */
  def intersects(segment: Segment): Boolean =
    val d = segment.d
    val denominator = direction cross d
    val w = segment.vertex1 - point
    if denominator == 0 then
      // Parallel: only collinear overlap counts.
      (w cross direction) == 0 && (contains(segment.vertex1) || contains(segment.vertex2))
    else
      val t = (w cross d) / denominator // parameter along the ray
      val u = (w cross direction) / denominator // parameter along the segment
      t >= 0 && u >= 0 && u <= 1

  /** True if `p` lies on this ray. */
  def contains(p: Vector2D): Boolean =
    val w = p - point
    (w cross direction) == 0 && (w dot direction) >= 0
