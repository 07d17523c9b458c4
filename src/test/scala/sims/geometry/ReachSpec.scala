package sims.geometry

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks

class ReachSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  private def exact(squared: Double, reach: Double): Boolean = math.sqrt(squared) - reach <= 0

  test("squares a few ulps either side of the squared reach get the square root's answer") {
    // Comparing squares alone would differ here: the square root of a square just above
    // reach * reach often rounds to reach itself.
    var naiveWouldDiffer = 0
    for reach <- Seq(0.1, 0.2, 0.24, 0.3, 1.0 / 3, 1.7, 5.0, 1e-100, 1e100, 1e-150, 1e150); k <- -64 to 64 do
      var squared = reach * reach
      for _ <- 0 until math.abs(k) do squared = if k > 0 then math.nextUp(squared) else math.nextDown(squared)
      withClue(s"reach $reach, squared $squared: ") { Reach.within(squared, reach) shouldBe exact(squared, reach) }
      if (squared <= reach * reach) != exact(squared, reach) then naiveWouldDiffer += 1
    naiveWouldDiffer should be > 0
  }

  test("random distances and reaches over 400 orders of magnitude") {
    val magnitude = Gen.choose(-200.0, 200.0).map(e => math.pow(10, e))
    val relative = Gen.oneOf(Gen.choose(-1e-6, 1e-6), Gen.choose(-2.0, 2.0), Gen.const(0.0))
    forAll(magnitude, relative, minSuccessful(5000)) { (reach, r) =>
      val distance = reach * (1 + r)
      val squared = distance * distance
      Reach.within(squared, reach) shouldBe exact(squared, reach)
    }
  }

  test("zero, subnormal, huge and non-finite inputs") {
    for
      reach <- Seq(0.0, Double.MinPositiveValue, 1e-160, 1e-300, 1e160, 1e300, Double.MaxValue, Double.PositiveInfinity)
      squared <- Seq(0.0, Double.MinPositiveValue, 1e-320, 1e-300, 1.0, 1e300, Double.MaxValue, Double.PositiveInfinity,
        Double.NaN)
    do withClue(s"reach $reach, squared $squared: ") { Reach.within(squared, reach) shouldBe exact(squared, reach) }
  }
