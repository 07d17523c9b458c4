package sims.geometry

/** The narrowphase's test of whether something is within reach of a point: given the squared
  * distance, the answer of `sqrt(squared) - reach <= 0` (SiMS's contact rule, in doubles), to
  * the bit, but without the square root unless the distance is within a billionth of the reach.
  * The tests run for every candidate pair before each pass of the classic step, and most pairs
  * are clearly apart or clearly overlapping.
  */
private[sims] object Reach:
  // Squares and reaches between these bounds are normal doubles, so a relative margin of 1e-9
  // on the squared reach is far beyond the rounding of the square and of the square root.
  private inline val Smallest = 1e-280
  private inline val Largest = 1e280
  private inline val Margin = 1e-9

  /** Whether `sqrt(squared) - reach <= 0`, computed in doubles. */
  def within(squared: Double, reach: Double): Boolean =
    val reachSquared = reach * reach
    val normal = reachSquared > Smallest && reachSquared < Largest
    if normal && squared > reachSquared * (1 + Margin) then false
    else if normal && squared < reachSquared * (1 - Margin) then true
    else math.sqrt(squared) - reach <= 0
