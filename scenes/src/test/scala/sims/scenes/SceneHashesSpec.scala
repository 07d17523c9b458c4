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
    "BallStack" -> ("e7269e6171ba7c59", "8236e6ef21cc3558"),
    "Chain" -> ("329c2311e46b8cad", "19e793c4f0e1814a"),
    "Stacking" -> ("219a2f406068eed8", "de051592ff0db53a"),
    "Restitution" -> ("b29165b804fd1ce2", "b3d5223190ccd2e4"),
    "Friction" -> ("528283d4e2da794e", "90b831d258a1a7c2"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "806c69bf53d4e535"),
    "Cup" -> ("ba654fa1de9da85f", "18c0ea1c21b49386"),
    "Carriage" -> ("ca3eaf59383651ed", "026d567fbd835ded"),
    "Wave" -> ("9a529cbc8bebf5ad", "1bb329a0e82cfd11"),
    "Atom" -> ("596f109ecd66714b", "24c26618542f226e"),
    "Cannon" -> ("94d0f0e9283ef7fb", "cbe5a2d6d7fa9407"),
    "Pylon" -> ("398ec6b1d15a72d7", "29300b273940e29a"),
    "Ragdoll" -> ("268f8d75638fda2c", "ea54edaecc3614c1"),
    "CompositeShape" -> ("749a252abb71bf86", "99414c336934210d"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "d6573bd38377a358"),
    "Pile" -> ("38e39babb7ebe442", "6994a2aa31b2cf4c"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "9e4c785d04cefc36"),
    "Dominoes" -> ("33e2a058c6177ac8", "b4f43bd241e43921"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "3b746f22bc43df8d"),
    "Filtering" -> ("b84810ed2b2eb563", "240d2b860f87bb1b"),
    "Shapes" -> ("fcd4608cf04ed625", "5b998c99660a292b"),
    "Sensors" -> ("57e39aba131d15e2", "3f7e9c03c75edbe4"),
    "Bullet" -> ("85e2f8af98216aea", "a44bc83b8818a3b2"),
    "Platformer" -> ("0e01a784731f675e", "3531f4977d4de1b6"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "02d8df13961d4b16"),
    "Car" -> (SoftOnly, "0e87992dfcb17fda"),
    "Bridge" -> (SoftOnly, "7aec527f3050711d"),
    "Windmill" -> (SoftOnly, "0efaf34fd7306f2e")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
