package sims

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.solver.SoftStep

/** The soft step's own golden hashes: the golden scenes stepped with `SoftStep()` give these
  * bits. A refactoring or speed work on the soft step must keep them; a deliberate change of
  * its results updates them in the same commit, saying why (unlike the classic step's, which
  * changed only once, for the portable elementary functions: see PerformanceRegressionSpec).
  * Changed for the portable elementary functions, then for restitution from the approach before
  * the substeps and circles' manifolds computed every step (energy and angular momentum), then
  * for the joint trees' compliance in the solve pass (a tree near a singular pose gained energy),
  * then for the joint trees solved by a leaner elimination (the same arithmetic, rounded
  * differently) and left alone in the relax passes before another substep when nothing else acts
  * on them, and the substeps' turns integrated by the angle h w itself (not atan(h w)), then for
  * the contacts' passes taking the two halves of the list in turn, then for the joint trees'
  * chain links eliminated before their joints (the same solution, rounded differently), then
  * for the contact passes' arithmetic regrouped so that fewer operations wait on the last
  * impulse (the same impulses, rounded differently), then for a contact's second point taking
  * its first point's impulse through their coupling, the bodies both at once (the same
  * Gauss-Seidel, rounded differently), then for the approach bound of a circle on its body's
  * centre taken without the body's spin (fewer speculative contacts for spinning balls), then
  * for the warm start of a contact turnless on both sides giving its normal impulse no turn (as
  * its passes do; the turn was the rounding of a moment about an arm along the normal), then
  * for a substep's turn brought back to length 1 by a Newton step rather than a root and two
  * divisions (the same to rounding, rounded differently).
  */
class SoftStepGoldenSpec extends AnyFunSuite with Matchers:
  import PerformanceRegressionSpec.{golden, hash}

  private def soft(name: String, steps: Int): String =
    val world = golden(name)
    world.solver = SoftStep()
    for _ <- 1 to steps do world.step()
    hash(world)

  test("golden-ballpit-300 under SoftStep after 240 steps") {
    soft("golden-ballpit-300", 240) shouldBe "56eeb1e90fe3641d"
  }

  test("golden-pyramid-12 under SoftStep after 240 steps") {
    soft("golden-pyramid-12", 240) shouldBe "7eebf49e3e44837c"
  }

  test("golden-mixed under SoftStep after 240 steps") {
    soft("golden-mixed", 240) shouldBe "1f79bf067b0b2f1a"
  }
