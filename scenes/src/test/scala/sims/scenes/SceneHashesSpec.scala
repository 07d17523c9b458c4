package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import sims.PerformanceRegressionSpec.hash
import sims.solver.{ClassicStep, SoftStep}

/** Every example scene after 200 steps under each step, bit for bit: a refactoring of either
  * step, of the collision stages or of the world keeps all of these. A deliberate change of a
  * step's results updates its column in the same commit, saying why.
  */
class SceneHashesSpec extends AnyFunSuite:
  import SceneHashesSpec.*

  for (name, (classic, soft)) <- Expected do
    test(s"$name after $Steps steps under ClassicStep and under SoftStep"):
      assert(stepped(name, soft = false) == classic, "ClassicStep")
      assert(stepped(name, soft = true) == soft, "SoftStep")

  test("every example scene has its hashes"):
    assert(Expected.map(_._1) == Scenes.all.map(_.name))

object SceneHashesSpec:
  val Steps = 200

  /** The scene stepped `Steps` times under the chosen step; its state's hash. */
  def stepped(name: String, soft: Boolean): String =
    val world = Scenes.find(name).get.build().world
    world.solver = if soft then SoftStep() else ClassicStep
    for _ <- 1 to Steps do world.step()
    hash(world)

  /** Per scene: the hash under ClassicStep, then under SoftStep. */
  val Expected: Seq[(String, (String, String))] = Seq(
    "BallStack" -> ("e7269e6171ba7c59", "796e7fb5bb179a69"),
    "Chain" -> ("329c2311e46b8cad", "35050fb94efad8b6"),
    "Stacking" -> ("219a2f406068eed8", "43176cecd470f634"),
    "Restitution" -> ("b29165b804fd1ce2", "d3b9741d5d565bc7"),
    "Friction" -> ("528283d4e2da794e", "7cca8f606a2b989e"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "452dc464a74e2f44"),
    "Cup" -> ("ba654fa1de9da85f", "b18008fb13ca927a"),
    "Carriage" -> ("ca3eaf59383651ed", "09b3d927097314bd"),
    "Wave" -> ("9a529cbc8bebf5ad", "1f9ebdbbffc9eb1c"),
    "Atom" -> ("596f109ecd66714b", "6d4f3c6983d5fe27"),
    "Cannon" -> ("94d0f0e9283ef7fb", "96e85d19fd32e760"),
    "Pylon" -> ("398ec6b1d15a72d7", "6bb4bd84b83d4ece"),
    "Ragdoll" -> ("268f8d75638fda2c", "430d5228c06bc58a"),
    "CompositeShape" -> ("749a252abb71bf86", "cd9f455dc667225d"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "b1db4b36c9d10ad1"),
    "Pile" -> ("38e39babb7ebe442", "93bc149658cc5a1a"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "e0d170ccd845cea2"),
    "Dominoes" -> ("33e2a058c6177ac8", "f57af9626db2ba44"),
    "Queries" -> ("c2981454928b775a", "cb716767aed74a98"),
    "Filtering" -> ("b84810ed2b2eb563", "ce4a1cf7631afc00"),
    "Shapes" -> ("fcd4608cf04ed625", "ab23d52e810f0621"),
    "Sensors" -> ("57e39aba131d15e2", "59f8a749831fb2b1"),
    "Bullet" -> ("85e2f8af98216aea", "c9689f1f16f6fb71")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do println(s"""    "${s.name}" -> ("${stepped(s.name, soft = false)}", "${stepped(s.name, soft = true)}"),""")
