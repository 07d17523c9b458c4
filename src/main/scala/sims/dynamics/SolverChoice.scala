package sims.dynamics

import sims.dynamics.joints.Joint
import sims.solver.{ClassicStep, Solver}

/** A world's solver, and the check that the classic step is chosen only for joints it can
  * step: a motor, a spring, a break force or a joint kind SiMS 1.2 has not is the soft step's.
  */
trait SolverChoice:
  this: World =>

  private var _solver: Solver = ClassicStep

  /** What `step()` runs (default [[sims.solver.ClassicStep]]); may be switched at any time. */
  def solver: Solver = _solver

  /** Chooses the solver of the next steps; must not be null. Switching to the classic step
    * fails, changing nothing, while a joint has a feature only the soft step steps (a motor, a
    * spring, a break force, or a kind SiMS 1.2 has not: weld, wheel, motor joint).
    */
  def solver_=(value: Solver): Unit =
    if value == null then throw IllegalArgumentException("solver must not be null")
    if value eq ClassicStep then
      jointList.foreach(j => classicStepProblem(j).foreach(p => throw IllegalArgumentException(p)))
    // Only the soft step keeps bodies asleep; any other starts with every body awake.
    if !(value eq _solver) then wakeAll()
    _solver = value

  /** Why the world's solver cannot step `joint`, or None (only the classic step refuses some). */
  private[sims] def classicProblem(joint: Joint): Option[String] =
    if _solver eq ClassicStep then classicStepProblem(joint) else None

  /** Why the classic step cannot step `joint`, or None. */
  private def classicStepProblem(joint: Joint): Option[String] =
    // A match, not `map`: checked for every joint before every step, it must not allocate.
    joint.softStepFeature match
      case Some(feature) =>
        Some(s"$joint has $feature, which ClassicStep (SiMS 1.2's step) cannot step: use the soft step, " +
          "world.solver = SoftStep()")
      case None => None
