package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import sims.PerformanceRegressionSpec.hash
import sims.solver.{ClassicStep, SoftStep}

/** Every example scene after 200 steps under each step (a soft-step-only scene under the soft
  * step alone), bit for bit: a refactoring of either
  * step, of the collision stages or of the world keeps all of these. A deliberate change of a
  * step's results updates its column in the same commit, saying why.
  */
class SceneHashesSpec extends AnyFunSuite:
  import SceneHashesSpec.*

  for (name, (classic, soft)) <- Expected do
    if classic == SoftOnly then
      test(s"$name after $Steps steps under SoftStep (it runs under the soft step only)"):
        assert(stepped(name, soft = true) == soft, "SoftStep")
    else
      // The pile (hundreds of bodies) is the one long simulation here: the Node run and the
      // coverage run leave it out (the JVM run checks it; PlatformHashesSpec compares platforms).
      val tags = if name == "Pile" then Seq(sims.SlowTest) else Nil
      test(s"$name after $Steps steps under ClassicStep and under SoftStep", tags*):
        assert(stepped(name, soft = false) == classic, "ClassicStep")
        assert(stepped(name, soft = true) == soft, "SoftStep")

  test("every example scene has its hashes, the soft-step-only scenes the marker in the classic column"):
    assert(Expected.map(_._1) == Scenes.all.map(_.name))
    for (name, (classic, _)) <- Expected do assert((classic == SoftOnly) == Scenes.find(name).get.softStepOnly, name)

object SceneHashesSpec:
  val Steps = 200

  /** What the classic column holds for a scene that runs under the soft step only. */
  val SoftOnly = "soft only"

  /** The scene stepped `Steps` times under the chosen step; its state's hash. */
  def stepped(name: String, soft: Boolean): String =
    val world = Scenes.find(name).get.build().world
    world.solver = if soft then SoftStep() else ClassicStep
    for _ <- 1 to Steps do world.step()
    hash(world)

  /** Per scene: the hash under ClassicStep, then under SoftStep. */
  val Expected: Seq[(String, (String, String))] = Seq(
    "BallStack" -> ("e7269e6171ba7c59", "94add31161e7d058"),
    "Chain" -> ("329c2311e46b8cad", "b7cd355b052dd3d4"),
    "Stacking" -> ("219a2f406068eed8", "3e6710b05355ad7f"),
    "Restitution" -> ("b29165b804fd1ce2", "b3d5223190ccd2e4"),
    "Friction" -> ("528283d4e2da794e", "90b831d258a1a7c2"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "4e2f57c3d1ae44d6"),
    "Cup" -> ("ba654fa1de9da85f", "9c837af48cbd46a0"),
    "Carriage" -> ("ca3eaf59383651ed", "4ebf830305392b69"),
    "Wave" -> ("9a529cbc8bebf5ad", "1bb329a0e82cfd11"),
    "Atom" -> ("596f109ecd66714b", "24c26618542f226e"),
    "Cannon" -> ("94d0f0e9283ef7fb", "26959693f4f07aea"),
    "Pylon" -> ("398ec6b1d15a72d7", "29300b273940e29a"),
    "Ragdoll" -> ("268f8d75638fda2c", "7e6e3e9d0652d8fb"),
    "CompositeShape" -> ("749a252abb71bf86", "0a7c12dfa18da991"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "7eb424b020c11a20"),
    "Pile" -> ("38e39babb7ebe442", "a3639b5e92471b25"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "9e4c785d04cefc36"),
    "Dominoes" -> ("33e2a058c6177ac8", "58e74ef30a51dc32"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "16e5da9dd97c99ff"),
    "Filtering" -> ("b84810ed2b2eb563", "4ba1f1af7ffaa67d"),
    "Shapes" -> ("fcd4608cf04ed625", "63df6995e351ef4b"),
    "Sensors" -> ("57e39aba131d15e2", "0eaeb6820a69c1ae"),
    "Bullet" -> ("85e2f8af98216aea", "6ff4a71d4a37bed2"),
    "Platformer" -> ("0e01a784731f675e", "b6a684c9c0c625bf"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "7e803b7dcac2a7a0"),
    "Car" -> (SoftOnly, "39f714262e9ab988"),
    "Bridge" -> (SoftOnly, "14db9d723aac8d78"),
    "Windmill" -> (SoftOnly, "89c8b326d55524de")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
