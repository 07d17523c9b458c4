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
    "BallStack" -> ("e7269e6171ba7c59", "9565e816a3fca208"),
    "Chain" -> ("329c2311e46b8cad", "58eb736d9963dbd9"),
    "Stacking" -> ("219a2f406068eed8", "b9ec31cc8cd86b2c"),
    "Restitution" -> ("b29165b804fd1ce2", "313fc4e8e2c7644f"),
    "Friction" -> ("528283d4e2da794e", "7cca8f606a2b989e"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "14d484cc5b92303e"),
    "Cup" -> ("ba654fa1de9da85f", "a829cd07243e4667"),
    "Carriage" -> ("ca3eaf59383651ed", "b9731f246a9bc65d"),
    "Wave" -> ("9a529cbc8bebf5ad", "4f69a2c9645ad8f9"),
    "Atom" -> ("596f109ecd66714b", "d54786120c3de6de"),
    "Cannon" -> ("94d0f0e9283ef7fb", "0b9ad3751cc1d16c"),
    "Pylon" -> ("398ec6b1d15a72d7", "d9275184a2088c1e"),
    "Ragdoll" -> ("268f8d75638fda2c", "abfb8ac963a57b8e"),
    "CompositeShape" -> ("749a252abb71bf86", "5d3c2cf8c3eb1d88"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "a3261846c6b10f0f"),
    "Pile" -> ("38e39babb7ebe442", "11480d56a1dfcaab"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "942b1bda84a1e331"),
    "Dominoes" -> ("33e2a058c6177ac8", "2df4e31ef82148ad"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "36cd41b27f54634d"),
    "Filtering" -> ("b84810ed2b2eb563", "b3749fe374799047"),
    "Shapes" -> ("fcd4608cf04ed625", "8642baf506243e0f"),
    "Sensors" -> ("57e39aba131d15e2", "0445d97369d7988f"),
    "Bullet" -> ("85e2f8af98216aea", "deb9d871b2271578"),
    "Platformer" -> ("0e01a784731f675e", "b493319b076368c7"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "1edc90decfaed59c"),
    "Car" -> (SoftOnly, "9dc81bce019a6309"),
    "Bridge" -> (SoftOnly, "637d9ee1f597958c"),
    "Windmill" -> (SoftOnly, "177b8bba7ba67f22")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
