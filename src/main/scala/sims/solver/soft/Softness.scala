package sims.solver.soft

/** The coefficients of a soft constraint (see docs/two-solvers.md): a constraint that behaves
  * like a damped spring of natural frequency `hertz` and damping ratio `zeta`, solved
  * implicitly over a substep of length h, so it is stable for any stiffness. With
  * omega = 2 pi hertz, a1 = 2 zeta + h omega, a2 = h omega a1, a3 = 1 / (1 + a2):
  *   biasRate = omega / a1      (the fraction of the error C removed per second)
  *   massScale = a2 a3          (the part of the rigid impulse applied)
  *   impulseScale = a3          (how much of the accumulated impulse is taken back)
  * and a step's impulse is lambda = -m massScale (Cdot + biasRate C) - impulseScale lambdaAcc.
  * A hertz of 0 makes a rigid constraint without bias (biasRate 0, massScale 1, impulseScale 0).
  */
private[sims] final class Softness:
  /** Fraction of the position error turned into velocity per second, 1/s. */
  var biasRate: Double = 0
  /** Scale of the effective mass, 0 to 1. */
  var massScale: Double = 1
  /** Scale of the accumulated impulse taken back, 0 to 1. */
  var impulseScale: Double = 0

  /** Sets the coefficients for stiffness `hertz`, damping ratio `zeta` and substep `h`. */
  def set(hertz: Double, zeta: Double, h: Double): Unit =
    Softness.write(hertz, zeta, h, scratch, 0)
    biasRate = scratch(0)
    massScale = scratch(1)
    impulseScale = scratch(2)

  private val scratch = new Array[Double](3)

/** The coefficients' formulas. */
private[sims] object Softness:
  /** Writes biasRate, massScale and impulseScale for stiffness `hertz`, damping ratio `zeta` and
    * substep `h` to `into(at)`, `into(at + 1)` and `into(at + 2)`.
    */
  def write(hertz: Double, zeta: Double, h: Double, into: Array[Double], at: Int): Unit =
    if hertz == 0 then
      into(at) = 0
      into(at + 1) = 1
      into(at + 2) = 0
    else
      val omega = 2 * math.Pi * hertz
      val a1 = 2 * zeta + h * omega
      val a2 = h * omega * a1
      val a3 = 1 / (1 + a2)
      into(at) = omega / a1
      into(at + 1) = a2 * a3
      into(at + 2) = a3
