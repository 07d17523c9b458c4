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
    "BallStack" -> ("e7269e6171ba7c59", "14388238aae2acc5"),
    "Chain" -> ("329c2311e46b8cad", "ac8860b7583675b8"),
    "Stacking" -> ("219a2f406068eed8", "41221be02f6b1761"),
    "Restitution" -> ("b29165b804fd1ce2", "313fc4e8e2c7644f"),
    "Friction" -> ("528283d4e2da794e", "6eb0528698b4d8c7"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "c9d7e882c25f3259"),
    "Cup" -> ("ba654fa1de9da85f", "af8d0316551e9557"),
    "Carriage" -> ("ca3eaf59383651ed", "59a1de130ddc5b03"),
    "Wave" -> ("9a529cbc8bebf5ad", "68739e5f33eaec24"),
    "Atom" -> ("596f109ecd66714b", "d54786120c3de6de"),
    "Cannon" -> ("94d0f0e9283ef7fb", "545a77d25e79d417"),
    "Pylon" -> ("398ec6b1d15a72d7", "1f2c87199ae50dc0"),
    "Ragdoll" -> ("268f8d75638fda2c", "013ab71470a86bfe"),
    "CompositeShape" -> ("749a252abb71bf86", "9fab38951b7d725b"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "489ff447289023b2"),
    "Pile" -> ("38e39babb7ebe442", "f1cd4c29e4bb258b"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "68aa60d97bb6daad"),
    "Dominoes" -> ("33e2a058c6177ac8", "762740db2ce464c8"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "1f29f9b4a2ca85af"),
    "Filtering" -> ("b84810ed2b2eb563", "d6f5945ceea8aad2"),
    "Shapes" -> ("fcd4608cf04ed625", "a3f705df77f63a44"),
    "Sensors" -> ("57e39aba131d15e2", "a564944614c088da"),
    "Bullet" -> ("85e2f8af98216aea", "dad611b28a167f6e"),
    "Platformer" -> ("0e01a784731f675e", "ff62675e72ef96da"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "d42cc924d5b6166a"),
    "Car" -> (SoftOnly, "2fa11b1de72e32b8"),
    "Bridge" -> (SoftOnly, "d1f7f6d76bc72977"),
    "Windmill" -> (SoftOnly, "7a3c86d6c816af6e")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
