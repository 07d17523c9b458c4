package sims.sweep

import sims.dynamics.World

/** When a run stops: after `maxSteps` steps, or sooner, at the first step after which
  * `condition` holds (checked after every step, and before the first).
  */
final case class Stop(maxSteps: Int, condition: Option[World => Boolean] = None):
  require(maxSteps >= 0, s"maxSteps must be at least 0, got $maxSteps")

  override def toString: String =
    if condition.isEmpty then s"Stop(after $maxSteps steps)" else s"Stop(when a condition holds, at most $maxSteps steps)"

/** The two ways to stop. */
object Stop:
  /** Runs exactly `steps` steps. */
  def after(steps: Int): Stop = Stop(steps)

  /** Runs until `condition` holds, at most `maxSteps` steps. */
  def when(maxSteps: Int)(condition: World => Boolean): Stop = Stop(maxSteps, Some(condition))
