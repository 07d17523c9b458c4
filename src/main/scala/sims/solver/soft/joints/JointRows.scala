package sims.solver.soft.joints

/** Where a joint writes its rows at the current substep for the direct solver ([[JointTrees]]):
  * for each row r (at most two), the Jacobian's three entries (vx, vy, w) for body 1 and for
  * body 2, and the position error C, straight into the solver's arrays (no copy per pass).
  */
private[sims] final class JointRows:
  /** Number of rows, 1 or 2. */
  var count: Int = 0
  // Body 1's entry (r, c) at jacobians(base + 3 r + c), body 2's at base + 6 + 3 r + c; the
  // error of row r at errors(errorBase + r).
  private var jacobians = new Array[Double](12)
  private var base = 0
  private var errors = new Array[Double](2)
  private var errorBase = 0

  /** Points the rows at `jacobians(base until base + 12)` and `errors(errorBase until errorBase + 2)`. */
  def target(jacobians: Array[Double], base: Int, errors: Array[Double], errorBase: Int): Unit =
    // A reference stored costs the garbage collector's write barrier: only when it changes (the
    // direct solver points every joint of a pass at the same arrays).
    if this.jacobians ne jacobians then this.jacobians = jacobians
    if this.errors ne errors then this.errors = errors
    this.base = base
    this.errorBase = errorBase

  /** Sets row r: body 1's entries, body 2's entries and the error. */
  def set(r: Int, a1: Double, b1: Double, c1: Double, a2: Double, b2: Double, c2: Double, error: Double): Unit =
    val o = base + 3 * r
    jacobians(o) = a1; jacobians(o + 1) = b1; jacobians(o + 2) = c1
    jacobians(o + 6) = a2; jacobians(o + 7) = b2; jacobians(o + 8) = c2
    errors(errorBase + r) = error
