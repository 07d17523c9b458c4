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
    "BallStack" -> ("e7269e6171ba7c59", "0375a983dfab7d28"),
    "Chain" -> ("329c2311e46b8cad", "0d5286f2169ceaf6"),
    "Stacking" -> ("219a2f406068eed8", "de051592ff0db53a"),
    "Restitution" -> ("b29165b804fd1ce2", "b3d5223190ccd2e4"),
    "Friction" -> ("528283d4e2da794e", "90b831d258a1a7c2"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "806c69bf53d4e535"),
    "Cup" -> ("ba654fa1de9da85f", "9edca24422ec7619"),
    "Carriage" -> ("ca3eaf59383651ed", "916f92acc4c7f750"),
    "Wave" -> ("9a529cbc8bebf5ad", "1bb329a0e82cfd11"),
    "Atom" -> ("596f109ecd66714b", "24c26618542f226e"),
    "Cannon" -> ("94d0f0e9283ef7fb", "3c540e2ec152aaac"),
    "Pylon" -> ("398ec6b1d15a72d7", "29300b273940e29a"),
    "Ragdoll" -> ("268f8d75638fda2c", "c030c4f889a537a6"),
    "CompositeShape" -> ("749a252abb71bf86", "99414c336934210d"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "ebea277ffa02b8ac"),
    "Pile" -> ("38e39babb7ebe442", "cf1f1e2a5b443dbd"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "9e4c785d04cefc36"),
    "Dominoes" -> ("33e2a058c6177ac8", "e23bafb8f4f1fd63"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "378e9202a9e6967d"),
    "Filtering" -> ("b84810ed2b2eb563", "e38f014d67dd500a"),
    "Shapes" -> ("fcd4608cf04ed625", "817b7710126537be"),
    "Sensors" -> ("57e39aba131d15e2", "66ee36ed914d7bf2"),
    "Bullet" -> ("85e2f8af98216aea", "2c74210b7c82c7d4"),
    "Platformer" -> ("0e01a784731f675e", "3531f4977d4de1b6"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "02d8df13961d4b16"),
    "Car" -> (SoftOnly, "0b8ba48e6c02c261"),
    "Bridge" -> (SoftOnly, "7b17ea43d3cff1bb"),
    "Windmill" -> (SoftOnly, "a20b584691d77028")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
