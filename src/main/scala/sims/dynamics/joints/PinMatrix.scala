package sims.dynamics.joints

/** The revolute joint's 2x2 system K P = b, set up and solved in place (fields rather than
  * objects, so the iterations allocate nothing). Each step that solves a pin owns one, so the
  * classic and the soft step never share its fields.
  */
private[sims] final class PinMatrix:
  /** K, row by row, as last set up by `setUp`. */
  var k11, k12, k21, k22 = 0.0
  /** P, as last found by `solve`. */
  var solutionX, solutionY = 0.0

  /** Sets K to the change of the pin points' relative velocity per unit impulse, when the
    * impulse acts at arms (b1x, b1y), (b2x, b2y) and the pin points are at arms (a1x, a1y),
    * (a2x, a2y), for bodies of inverse masses and inertias (invMass1, invI1), (invMass2, invI2):
    * (1/m1 + 1/m2) E + sum over both bodies of 1/I [a.y b.y, -a.y b.x; -a.x b.y, a.x b.x].
    * With a = b this is the symmetric K of the revolute joint's derivation. Returns its
    * determinant.
    */
  def setUp(invMass1: Double, invI1: Double, invMass2: Double, invI2: Double, a1x: Double, a1y: Double,
      b1x: Double, b1y: Double, a2x: Double, a2y: Double, b2x: Double, b2y: Double): Double =
    val invMass = invMass1 + invMass2
    k11 = invMass + invI1 * a1y * b1y + invI2 * a2y * b2y
    k12 = -invI1 * a1y * b1x - invI2 * a2y * b2x
    k21 = -invI1 * a1x * b1y - invI2 * a2x * b2y
    k22 = invMass + invI1 * a1x * b1x + invI2 * a2x * b2x
    k11 * k22 - k12 * k21

  /** Solves K P = (bx, by) for the matrix last set up, with its determinant; P = 0 when K is
    * singular (both bodies fixed).
    */
  def solve(determinant: Double, bx: Double, by: Double): Unit =
    if determinant == 0 then
      solutionX = 0; solutionY = 0
    else
      solutionX = (k22 * bx - k12 * by) / determinant
      solutionY = (k11 * by - k21 * bx) / determinant
