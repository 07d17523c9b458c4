package sims

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.World
import sims.scenes.{Scenes, StateFingerprint}

/** Golden hashes of whole simulations, recorded with the straightforward implementation
  * before any speed work (and once more when the library's angles moved to PortableMath's
  * elementary functions, the same bits on every platform): optimisations of the step (solver, narrowphase, broadphase) must
  * keep every body's doubles bit for bit. A changed hash means the floating-point results
  * changed; it must never be updated silently. The scenes are `sims.scenes.TestScenes.golden`.
  */
class PerformanceRegressionSpec extends AnyFunSuite with Matchers:
  import PerformanceRegressionSpec.*

  test("a ballpit of 300 balls in a container: bit-identical after 240 steps") {
    val world = golden("golden-ballpit-300")
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "57d7bd6ffcded6a6"
  }

  test("a pyramid of 12 rows of boxes: bit-identical after 240 steps") {
    val world = golden("golden-pyramid-12")
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "69c4b2379db1083e"
  }

  test("mixed shapes, a two-shape body and a chain: bit-identical after 240 steps") {
    val world = golden("golden-mixed")
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "951c4692e4881ccf"
  }

/** The golden scenes by name, and the hash. */
object PerformanceRegressionSpec:
  /** A fresh world of the golden scene of this name (see `sims.scenes.TestScenes`). */
  def golden(name: String): World = Scenes.find(name).getOrElse(throw IllegalArgumentException(name)).build().world

  /** A hex digest of every body's position, rotation and velocities, in world order. */
  def hash(world: World): String = StateFingerprint(world)
