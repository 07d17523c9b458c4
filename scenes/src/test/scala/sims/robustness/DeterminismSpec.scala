package sims.robustness

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.World
import sims.scenes.TestScenes

/** Same inputs, same outputs, bit for bit. */
class DeterminismSpec extends AnyFunSuite with Matchers:

  /** The determinism scene, its bodies created in `allocationOrder`. */
  private def scene(allocationOrder: Seq[Int]): World = TestScenes.Determinism(allocationOrder).build().world

  test("the same scene built twice gives bit-identical trajectories over 10,000 steps", sims.SlowTest) {
    val a = scene(0 until 12)
    val b = scene(0 until 12)
    for i <- 1 to 10000 do
      a.step()
      b.step()
      if i % 1000 == 0 then StateHash(a) shouldBe StateHash(b)
  }

  test("creating the bodies in another order (other identity hashes) changes nothing", sims.SlowTest) {
    val a = scene(0 until 12)
    val b = scene((0 until 12).reverse)
    val c = scene(Seq(5, 3, 11, 0, 7, 1, 9, 2, 10, 4, 8, 6))
    for i <- 1 to 10000 do
      a.step(); b.step(); c.step()
      if i % 1000 == 0 then
        StateHash(b) shouldBe StateHash(a)
        StateHash(c) shouldBe StateHash(a)
  }
