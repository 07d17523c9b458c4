package sims

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.World
import sims.scenes.Scenes

/** Golden hashes of whole simulations, recorded with the straightforward implementation
  * before any speed work: optimisations of the step (solver, narrowphase, broadphase) must
  * keep every body's doubles bit for bit. A changed hash means the floating-point results
  * changed; it must never be updated silently. The scenes are `sims.scenes.TestScenes.golden`.
  */
class PerformanceRegressionSpec extends AnyFunSuite with Matchers:
  import PerformanceRegressionSpec.*

  test("a ballpit of 300 balls in a container: bit-identical after 240 steps") {
    val world = golden("golden-ballpit-300")
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "b8df93bf8445044d"
  }

  test("a pyramid of 12 rows of boxes: bit-identical after 240 steps") {
    val world = golden("golden-pyramid-12")
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "7cd60b3d14c6e925"
  }

  test("mixed shapes, a two-shape body and a chain: bit-identical after 240 steps") {
    val world = golden("golden-mixed")
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "4de67497cc14680b"
  }

/** The golden scenes by name, and the hash. */
object PerformanceRegressionSpec:
  /** A fresh world of the golden scene of this name (see `sims.scenes.TestScenes`). */
  def golden(name: String): World = Scenes.find(name).getOrElse(throw IllegalArgumentException(name)).build().world

  /** A hex digest of every body's position, rotation and velocities, in world order. */
  def hash(world: World): String =
    val digest = java.security.MessageDigest.getInstance("SHA-256")
    val buffer = java.nio.ByteBuffer.allocate(8 * 6)
    for b <- world.bodies do
      buffer.clear()
      buffer.putDouble(b.pos.x).putDouble(b.pos.y).putDouble(b.rotation)
      buffer.putDouble(b.linearVelocity.x).putDouble(b.linearVelocity.y).putDouble(b.angularVelocity)
      digest.update(buffer.array())
    digest.digest().take(8).map(byte => f"${byte & 0xff}%02x").mkString
