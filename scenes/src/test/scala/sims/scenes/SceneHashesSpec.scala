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
    "BallStack" -> ("e7269e6171ba7c59", "6157c3541e1ab87f"),
    "Chain" -> ("329c2311e46b8cad", "53eb01641b2f66e8"),
    "Stacking" -> ("219a2f406068eed8", "416ecc7fc2ca471e"),
    "Restitution" -> ("b29165b804fd1ce2", "64d060252fbd177c"),
    "Friction" -> ("528283d4e2da794e", "7cca8f606a2b989e"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "b71d3a47739babd9"),
    "Cup" -> ("ba654fa1de9da85f", "0716ebc2468e1488"),
    "Carriage" -> ("ca3eaf59383651ed", "bfe6fdef08792a31"),
    "Wave" -> ("9a529cbc8bebf5ad", "4f69a2c9645ad8f9"),
    "Atom" -> ("596f109ecd66714b", "d54786120c3de6de"),
    "Cannon" -> ("94d0f0e9283ef7fb", "bfb3aa04fe885369"),
    "Pylon" -> ("398ec6b1d15a72d7", "8ed20c3689a1283f"),
    "Ragdoll" -> ("268f8d75638fda2c", "dd21c2804c6ea5a7"),
    "CompositeShape" -> ("749a252abb71bf86", "c062a755642084a4"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "337e370be403e1e9"),
    "Pile" -> ("38e39babb7ebe442", "d60c8fc360069ede"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "ff80ec1720833acc"),
    "Dominoes" -> ("33e2a058c6177ac8", "915e744d57872f8d"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "97dc596db0185dfd"),
    "Filtering" -> ("b84810ed2b2eb563", "5d8a415671839322"),
    "Shapes" -> ("fcd4608cf04ed625", "def0d0782bb0bf4c"),
    "Sensors" -> ("57e39aba131d15e2", "eea470f65b052824"),
    "Bullet" -> ("85e2f8af98216aea", "b6e843f5fa439f0c"),
    "Platformer" -> ("0e01a784731f675e", "b493319b076368c7"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "64fc5ecf1fd3e3e7"),
    "Car" -> (SoftOnly, "9dc81bce019a6309"),
    "Bridge" -> (SoftOnly, "3035a6c0f8f1c36a"),
    "Windmill" -> (SoftOnly, "08678d6b890f8fd6")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
