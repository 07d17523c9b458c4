package sims.solver.soft.joints

/** One joint's rows at the current substep, as a joint gives them to the direct solver
  * ([[JointTrees]]): for each row r (at most two), the Jacobian's three entries (vx, vy, w) for
  * body 1 and for body 2, and the position error C.
  */
private[sims] final class JointRows:
  /** Number of rows, 1 or 2. */
  var count: Int = 0
  /** Row-major: entry (r, c) at r * 3 + c. */
  val jacobian1: Array[Double] = new Array[Double](6)
  /** Row-major: entry (r, c) at r * 3 + c. */
  val jacobian2: Array[Double] = new Array[Double](6)
  /** The position error of each row. */
  val positionError: Array[Double] = new Array[Double](2)

  /** Sets row r: body 1's entries, body 2's entries and the error. */
  def set(r: Int, a1: Double, b1: Double, c1: Double, a2: Double, b2: Double, c2: Double, error: Double): Unit =
    jacobian1(r * 3) = a1; jacobian1(r * 3 + 1) = b1; jacobian1(r * 3 + 2) = c1
    jacobian2(r * 3) = a2; jacobian2(r * 3 + 1) = b2; jacobian2(r * 3 + 2) = c2
    positionError(r) = error
