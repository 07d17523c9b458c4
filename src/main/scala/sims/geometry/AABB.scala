package sims.geometry

/** An axis-aligned bounding box from `minVertex` (lower left) to `maxVertex` (upper right). */
final case class AABB(minVertex: Vector2D, maxVertex: Vector2D):

  /** True if the two boxes overlap or touch. */
  def overlaps(other: AABB): Boolean =
    AABB.overlaps(minVertex.x, minVertex.y, maxVertex.x, maxVertex.y,
      other.minVertex.x, other.minVertex.y, other.maxVertex.x, other.maxVertex.y)

object AABB:
  /** Overlap test on raw coordinates, for hot loops. */
  private[sims] inline def overlaps(minX1: Double, minY1: Double, maxX1: Double, maxY1: Double,
      minX2: Double, minY2: Double, maxX2: Double, maxY2: Double): Boolean =
    minX1 <= maxX2 && minX2 <= maxX1 && minY1 <= maxY2 && minY2 <= maxY1
