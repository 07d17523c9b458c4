package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import sims.solver.{ClassicStep, SoftStep}

/** Five scenes (polygons, circles, joints) after 600 steps under each step: the same
  * fingerprints on the JVM and on Node (this test runs on both) and in Chromium (the playground's
  * browser test asks the page for the same runs). Any platform's own elementary functions in the
  * state, or any other platform-dependent arithmetic, would break them.
  */
class PlatformHashesSpec extends AnyFunSuite:
  import PlatformHashesSpec.*

  for (name, (classic, soft)) <- Expected do
    test(s"$name after $Steps steps: the fingerprints recorded on the JVM, under both steps"):
      assert(fingerprint(name, soft = false) == classic, "ClassicStep")
      assert(fingerprint(name, soft = true) == soft, "SoftStep")

object PlatformHashesSpec:
  val Steps = 600

  /** The scene stepped `Steps` times under the chosen step; its state's fingerprint. */
  def fingerprint(name: String, soft: Boolean): String =
    val world = Scenes.find(name).get.build().world
    world.solver = if soft then SoftStep() else ClassicStep
    for _ <- 1 to Steps do world.step()
    StateFingerprint(world)

  /** Per scene: the fingerprint under ClassicStep, then under SoftStep (recorded on the JVM). */
  val Expected: Seq[(String, (String, String))] = Seq(
    "Pyramid" -> ("dd5baa49fafec7ac", "d6573bd38377a358"),
    "BallStack" -> ("8db9759ae6989d8b", "8236e6ef21cc3558"),
    "Ragdoll" -> ("e86196be7f7d6310", "dca1a06d6ae7c81c"),
    "Chain" -> ("8abde10dfa3f46b7", "cb8be5cef40e16dc"),
    "Carriage" -> ("b61f7c5294100851", "632e95a2e18fb03b")
  )

  /** Prints the table above for the current code (run with `scenes/Test/runMain`). */
  @main def recordPlatformHashes(): Unit =
    for (name, _) <- Expected do
      println(s"""    "$name" -> ("${fingerprint(name, soft = false)}", "${fingerprint(name, soft = true)}"),""")
