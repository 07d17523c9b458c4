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
    "BallStack" -> ("f46bab91abf706c5", "aa543560b6b2d5e1"),
    "Chain" -> ("fed3e5ffc303dadd", "8b025efc0ae07db1"),
    "Stacking" -> ("f7e504ac46a61e96", "01b41c8f5883e9a2"),
    "Restitution" -> ("0b17ce0bf5e53417", "3e9a56605a3f8302"),
    "Friction" -> ("5e77dcf95377c961", "87a7e1963b8762b7"),
    "Spring" -> ("462b87d737945451", "9b79eb1065c9c4e8"),
    "Net" -> ("dc8acf955c7ba2c7", "7bd4d85decc5d9b3"),
    "Cup" -> ("82d041e167727b3f", "7c28e6cb566c9efa"),
    "Carriage" -> ("30d20d5df9cb7434", "58a1f07dd0957e1d"),
    "Wave" -> ("fb512f0f24b0631a", "c7032f5f9bb8ea1c"),
    "Atom" -> ("4efc041c0a5aab69", "2c28fae894b53d2d"),
    "Cannon" -> ("0eab30e1d482388c", "1678d539f26602fe"),
    "Pylon" -> ("33677466d510cac0", "7aa1432282dd68ac"),
    "Ragdoll" -> ("c3d5aaa310fe5333", "2b9c60fc7dd41446"),
    "CompositeShape" -> ("104d4553b183aec4", "bb146d342db36954"),
    "Pyramid" -> ("ae2d6bf9586ffe9a", "10a8df84a57a7b60"),
    "Pile" -> ("40b197eae3c190c9", "d585ec6091959176"),
    "NewtonsCradle" -> ("f24f19a6786c879c", "f41392bd2a73c379"),
    "Dominoes" -> ("a9a051cfb5a968ed", "05ffb7f91349e46e"),
    // Its hook pushes bodies at ray-cast hits: the circle cast measured from the line's closest
    // point (exact far from the origin) rounds them differently. The steps are unchanged.
    "Queries" -> ("f41bfe094172daf1", "4eb9b039de184c35"),
    "Filtering" -> ("7461ab57e5ca08a5", "c263a9d5d5ecff4c"),
    "Shapes" -> ("7cb3ab878f36afaf", "feba65c799496c21"),
    "Sensors" -> ("be2e599d9971278e", "21124083c3b2e716"),
    "Bullet" -> ("f2ee008771259cc4", "085e15a4d430593f")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordSceneHashes(): Unit =
    for s <- Scenes.all do println(s"""    "${s.name}" -> ("${stepped(s.name, soft = false)}", "${stepped(s.name, soft = true)}"),""")
