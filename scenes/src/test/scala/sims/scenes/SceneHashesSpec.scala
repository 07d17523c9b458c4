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
    "BallStack" -> ("e7269e6171ba7c59", "38388e5f37479480"),
    "Chain" -> ("329c2311e46b8cad", "0be806730af07ae8"),
    "Stacking" -> ("219a2f406068eed8", "f2ffbd6921455f29"),
    "Restitution" -> ("b29165b804fd1ce2", "2858c16428752720"),
    "Friction" -> ("528283d4e2da794e", "7cca8f606a2b989e"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "33eea80c1c585e29"),
    "Cup" -> ("ba654fa1de9da85f", "2fbae819c64a9b12"),
    "Carriage" -> ("ca3eaf59383651ed", "c3a0221f010f7da1"),
    "Wave" -> ("9a529cbc8bebf5ad", "1f9ebdbbffc9eb1c"),
    "Atom" -> ("596f109ecd66714b", "d54786120c3de6de"),
    "Cannon" -> ("94d0f0e9283ef7fb", "2f62a163d2b10af4"),
    "Pylon" -> ("398ec6b1d15a72d7", "9a5939592711529e"),
    "Ragdoll" -> ("268f8d75638fda2c", "51e4e100defde973"),
    "CompositeShape" -> ("749a252abb71bf86", "01d4643389a10286"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "ccb2364c69e22aa8"),
    "Pile" -> ("38e39babb7ebe442", "db6abce203545977"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "6aa0640c3f357e58"),
    "Dominoes" -> ("33e2a058c6177ac8", "67aab6b44f1689bd"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "2051c707e0d55d32"),
    "Filtering" -> ("b84810ed2b2eb563", "014c6ad5373da222"),
    "Shapes" -> ("fcd4608cf04ed625", "38609dbfe60fb20b"),
    "Sensors" -> ("57e39aba131d15e2", "522ed2e00ed04ce0"),
    "Bullet" -> ("85e2f8af98216aea", "b6e843f5fa439f0c"),
    "Platformer" -> ("0e01a784731f675e", "b493319b076368c7"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "8afb189631c8c37c")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do println(s"""    "${s.name}" -> ("${stepped(s.name, soft = false)}", "${stepped(s.name, soft = true)}"),""")
