package sims.examples

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
