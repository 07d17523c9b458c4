package sims.geometry

/** The interval `[lower, upper]` covered by a shape projected onto `axis`. */
final case class Projection(axis: Vector2D, lower: Double, upper: Double):

  /** True if the two intervals share at least one point. */
  def overlaps(other: Projection): Boolean = !(lower > other.upper || upper < other.lower)

  /** Length of the common part of the two intervals (0 when they are apart). */
  def overlap(other: Projection): Double = Projection.overlap(lower, upper, other.lower, other.upper)

object Projection:
  /** Length of the common part of `[lower1, upper1]` and `[lower2, upper2]`, at least 0. */
  private[sims] def overlap(lower1: Double, upper1: Double, lower2: Double, upper2: Double): Double =
    math.max(0.0, math.min(upper1, upper2) - math.max(lower1, lower2))
