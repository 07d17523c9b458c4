package sims.solver

import sims.collision.Contact
import sims.dynamics.World

/** What a world's `step()` runs: the stages of one time step, in order.
  *
  * The world saves its state before the step, finishes its events and runs its post-step hook
  * after it. A solver, inside `step`: advances the world's time (`world.advanceTime()`), names
  * each stage as it begins (`world.stage = "..."`), and calls `world.guard(stage, checked)`
  * after each stage that can produce a non-finite value, so that a failing step names its stage
  * and leaves the world as it was. Data a solver keeps between steps (scratch arrays, a contact
  * table) belongs to the world, in `world.workspace(kind, create)`, so one solver value can step
  * many worlds; what one step hands to the next implements [[sims.dynamics.CarriedState]]. Everything a solver
  * needs is public: one can be written outside the library. Two are built in: [[ClassicStep]]
  * (the default, SiMS 1.2's step) and `SoftStep`.
  */
trait Solver:
  /** Advances `world` by one `world.timeStep`. */
  def step(world: World): Unit

  /** The interval over which this solver integrates forces (the force joints' springs):
    * `world.timeStep` unless the solver substeps.
    */
  def forceInterval(world: World): Double = world.timeStep

  /** The contacts of `world`'s last step with this solver, as copies. */
  def contacts(world: World): IndexedSeq[Contact]

  /** Whether `step` reports the pairs that touch to the world's contact events itself (the
    * library's solvers do, as they find them); otherwise the world takes every contact of
    * `contacts` with a point at or below zero separation after each step.
    */
  private[sims] def reportsTouching: Boolean = false

  /** Whether the solver saves each body's state before it changes it, into the world's
    * `stateBeforeStep` (`saveBodies` or `saveBody`, then `bodiesSaved`), as it reads the bodies
    * anyway; otherwise the world saves them before the step.
    */
  private[sims] def savesBodies: Boolean = false

  /** Ends the contact events of `world`'s step, after `step` and the joints' breaking: the open
    * pairs that no longer touch end (see [[sims.collision.PairTracker.finishStep]]). A solver
    * with threads of its own may share the work out.
    */
  private[sims] def finishContactEvents(world: World): Unit = world.contactTracker.finishStep(world)
