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
    "BallStack" -> ("e7269e6171ba7c59", "988eb6812f8b03ac"),
    "Chain" -> ("329c2311e46b8cad", "453280a15d711c29"),
    "Stacking" -> ("219a2f406068eed8", "08548f9bf54054be"),
    "Restitution" -> ("b29165b804fd1ce2", "313fc4e8e2c7644f"),
    "Friction" -> ("528283d4e2da794e", "6eb0528698b4d8c7"),
    "Spring" -> ("ef30dc87c96e4fc0", "07360467ebed9b2a"),
    "Net" -> ("d58678c398eaf33a", "cc74fea5fe1eb24f"),
    "Cup" -> ("ba654fa1de9da85f", "691cfa6cd5a80541"),
    "Carriage" -> ("ca3eaf59383651ed", "7b232c30f5d317d5"),
    "Wave" -> ("9a529cbc8bebf5ad", "1bb329a0e82cfd11"),
    "Atom" -> ("596f109ecd66714b", "d54786120c3de6de"),
    "Cannon" -> ("94d0f0e9283ef7fb", "a9daa2c1193f3ca4"),
    "Pylon" -> ("398ec6b1d15a72d7", "1f2c87199ae50dc0"),
    "Ragdoll" -> ("268f8d75638fda2c", "bcab4c6ec39529b6"),
    "CompositeShape" -> ("749a252abb71bf86", "84fc548e418c6545"),
    "Pyramid" -> ("6fa8bba0b103b7ea", "99836b506ac2f1a2"),
    "Pile" -> ("38e39babb7ebe442", "1bda1b854ef9930c"),
    "NewtonsCradle" -> ("2bc439aacf19d9c3", "39e4c19d46205cb6"),
    "Dominoes" -> ("33e2a058c6177ac8", "115011452164d2e1"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently; the steps are unchanged by that.
    "Queries" -> ("4722ae2b3909f55a", "d4e070b0e582a571"),
    "Filtering" -> ("b84810ed2b2eb563", "38678b468333f866"),
    "Shapes" -> ("fcd4608cf04ed625", "250fdc55f96c5f4a"),
    "Sensors" -> ("57e39aba131d15e2", "4d9e86ecd71d7145"),
    "Bullet" -> ("85e2f8af98216aea", "72fe752ff08ada84"),
    "Platformer" -> ("0e01a784731f675e", "ff62675e72ef96da"),
    "LimitedRagdoll" -> ("fce65789c5e27c8f", "77e982d276812b0e"),
    "Car" -> (SoftOnly, "38a1c52d3cc68dac"),
    "Bridge" -> (SoftOnly, "05d6937cf9755749"),
    "Windmill" -> (SoftOnly, "578747e661d48e83")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do
      val classic = if s.softStepOnly then "SoftOnly" else s"\"${stepped(s.name, soft = false)}\""
      println(s"""    "${s.name}" -> ($classic, "${stepped(s.name, soft = true)}"),""")
