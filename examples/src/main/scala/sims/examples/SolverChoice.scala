package sims.examples

import sims.scenes.Scene
import sims.solver.{ClassicStep, Solver, SoftStep}

/** The solvers the examples offer, each with its defaults: SiMS's own step (the default) and
  * the soft step.
  *
  * @param argument the word that names it on the command line (`--solver soft`)
  * @param label how captions, the viewer and the log name it
  */
enum SolverChoice(val argument: String, val label: String):
  /** [[sims.solver.ClassicStep]], SiMS 1.2's step: the library's default. */
  case Classic extends SolverChoice("classic", "classic step")
  /** `SoftStep()`: substeps, soft contacts, warm starting, relaxation. */
  case Soft extends SolverChoice("soft", "soft step")

  /** A solver of this kind with its defaults, for `world.solver`. */
  def solver: Solver = this match
    case Classic => ClassicStep
    case Soft => SoftStep()

object SolverChoice:
  /** The choice named `argument` on the command line (`classic` or `soft`, any case), if any. */
  def named(argument: String): Option[SolverChoice] = values.find(_.argument.equalsIgnoreCase(argument))

  /** The solver that steps `scene` when `wanted` is chosen: `wanted`, or the soft step for a
    * scene that runs under the soft step only (`Scene.softStepOnly`).
    */
  def forScene(scene: Scene, wanted: SolverChoice): SolverChoice = if scene.softStepOnly then Soft else wanted

  /** The solvers `scene` may be stepped by: both, or the soft step alone for a soft-step-only scene. */
  def offeredFor(scene: Scene): Seq[SolverChoice] = if scene.softStepOnly then Seq(Soft) else values.toSeq
