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
    "BallStack" -> ("f46bab91abf706c5", "8a2c19b562460d7b"),
    "Chain" -> ("fed3e5ffc303dadd", "51946ab25dd69136"),
    "Stacking" -> ("f7e504ac46a61e96", "cf11eb5fe5603245"),
    "Restitution" -> ("0b17ce0bf5e53417", "108df6998b90ed79"),
    "Friction" -> ("5e77dcf95377c961", "87a7e1963b8762b7"),
    "Spring" -> ("462b87d737945451", "9b79eb1065c9c4e8"),
    "Net" -> ("dc8acf955c7ba2c7", "0c6d7eaad524feac"),
    "Cup" -> ("82d041e167727b3f", "03c7a2c1f162b99c"),
    "Carriage" -> ("30d20d5df9cb7434", "4d14339670200a93"),
    "Wave" -> ("fb512f0f24b0631a", "c7032f5f9bb8ea1c"),
    "Atom" -> ("4efc041c0a5aab69", "539efd9078a78e32"),
    "Cannon" -> ("0eab30e1d482388c", "c5878192445e5e45"),
    "Pylon" -> ("33677466d510cac0", "cb689a07be46c5ae"),
    "Ragdoll" -> ("c3d5aaa310fe5333", "91a0964457031e77"),
    "CompositeShape" -> ("104d4553b183aec4", "bf8d50635534551e"),
    "Pyramid" -> ("ae2d6bf9586ffe9a", "22143b8e9116b609"),
    "Pile" -> ("40b197eae3c190c9", "31da2cfd1585b23c"),
    "NewtonsCradle" -> ("f24f19a6786c879c", "f22f71d31065de1e"),
    "Dominoes" -> ("a9a051cfb5a968ed", "a17537cd4d93642c"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently. The steps are unchanged.
    "Queries" -> ("f41bfe094172daf1", "3e9e5e5b0720db88"),
    "Filtering" -> ("7461ab57e5ca08a5", "f1ba21bec9a8f60d"),
    "Shapes" -> ("7cb3ab878f36afaf", "9e8c3badc84cae9c"),
    "Sensors" -> ("be2e599d9971278e", "b49d54cd3ff012ad"),
    "Bullet" -> ("f2ee008771259cc4", "86cdff0a5e3b4f51")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do println(s"""    "${s.name}" -> ("${stepped(s.name, soft = false)}", "${stepped(s.name, soft = true)}"),""")
