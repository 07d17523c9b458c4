package sims.dynamics.joints

/** The prismatic joint's 2x2 system K lambda = b (line row and angle row), solved in place.
  * Each step that solves the joint owns one, so the classic and the soft step never share its
  * fields.
  */
private[sims] final class PrismaticMatrix:
  /** lambda, as last found by `solve`: the line impulse and the turn impulse. */
  var lineImpulse, turnImpulse = 0.0

  /** Solves K lambda = (lineRight, turnRight) with K as in the prismatic joint's derivation,
    * for bodies of inverse masses and inertias (invMass1, invI1), (invMass2, invI2) and the
    * angular terms a1 = (d + r1) x n, a2 = r2 x n; lambda = 0 when K is singular (both bodies
    * fixed).
    */
  def solve(invMass1: Double, invI1: Double, invMass2: Double, invI2: Double, angular1: Double, angular2: Double,
      lineRight: Double, turnRight: Double): Unit =
    val coupling = invI1 * angular1 + invI2 * angular2
    val k11 = invMass1 + invMass2 + invI1 * angular1 * angular1 + invI2 * angular2 * angular2
    val k22 = invI1 + invI2
    val determinant = k11 * k22 - coupling * coupling
    if determinant == 0 then
      lineImpulse = 0; turnImpulse = 0
    else
      lineImpulse = (k22 * lineRight - coupling * turnRight) / determinant
      turnImpulse = (k11 * turnRight - coupling * lineRight) / determinant
