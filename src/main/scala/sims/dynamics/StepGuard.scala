package sims.dynamics

/** What a world's guard checks after a stage of a step. */
enum Checked(val quantity: String):
  /** Every body's force and torque. */
  case Forces extends Checked("force")
  /** Every body's linear and angular velocity. */
  case Velocities extends Checked("velocity")
  /** Every body's position and rotation. */
  case Positions extends Checked("position")

/** The world's checks of a step. Before it: every joint's bodies are in the world, and the
  * solver can step every joint (a spring too stiff for its force interval cannot be). During it:
  * a solver names each stage as it begins (`stage`), and after each stage that can produce a
  * non-finite value calls `guard`, which fails the step (the world then restores its state
  * before the step) naming the first body whose checked quantity is not finite, and the stage.
  */
trait StepGuard:
  this: World =>

  private var _stage: String = StepGuard.NoStage
  // Set when the guard throws: its exception already names the body and the stage.
  private var guardFailed = false

  /** The stage of the step under way ("none" between steps), as its solver named it: the error
    * of a failed step names it.
    */
  def stage: String = _stage

  /** Names the stage of the step under way; for solvers, during `step()` only (a constant
    * string, so setting it allocates nothing).
    */
  def stage_=(name: String): Unit =
    requireStep("stage")
    if name == null then throw IllegalArgumentException("stage must not be null")
    _stage = name

  /** The world's own stages of a step: its start, its events and hook, and none after it. */
  protected def enterStage(name: String): Unit = _stage = name

  /** Fails unless a step is under way: `what` is for solvers, inside `step()`. */
  protected def requireStep(what: String): Unit =
    if _stage eq StepGuard.NoStage then
      throw IllegalStateException(s"$what is for a solver during step(), not between steps")

  /** Fails unless every joint's bodies are in the world and the solver can step every joint. */
  protected def checkJoints(): Unit =
    val joints = jointList
    val interval = solver.forceInterval(this) // the same for every joint
    var i = 0
    while i < joints.length do
      val j = joints(i)
      if !j.bodiesIn(this) then
        throw IllegalArgumentException(s"joint $j connects a body that is not in this world")
      // The time step or the masses may have changed since the joint joined.
      j.forceIntervalProblem(interval, solver).foreach(problem => throw IllegalStateException(problem))
      // A joint given a soft-step feature after it joined a classic world.
      this.classicProblem(j).foreach(problem => throw IllegalStateException(problem))
      i += 1

  /** Why the world's solver, the classic step, cannot step `joint`, or None (also under any
    * other solver).
    */
  private[sims] def classicProblem(joint: sims.dynamics.joints.Joint): Option[String]

  /** Why the solver cannot step `joint` (see `Joint.forceIntervalProblem`), or None. */
  protected def forceIntervalProblem(joint: sims.dynamics.joints.Joint): Option[String] =
    joint.forceIntervalProblem(solver.forceInterval(this), solver)

  /** Fails the step under way with an ArithmeticException naming the body and `stage` if any
    * body's `checked` quantity is not finite; `step()` then restores the world. For solvers.
    */
  def guard(stage: String, checked: Checked): Unit =
    val bodies = bodyList
    var i = 0
    while i < bodies.length do
      val b = bodies(i)
      val ok = checked match
        case Checked.Forces => finite(b.fx) && finite(b.fy) && finite(b.tau)
        case Checked.Velocities => finite(b.vx) && finite(b.vy) && finite(b.w)
        case Checked.Positions => finite(b.x) && finite(b.y) && finite(b.angle)
      if !ok then guardFailure(i, stage, checked)
      i += 1

  /** Fails the step under way: body i's checked quantity is not finite after `stage` (for a
    * solver that keeps the bodies' state elsewhere during the step and finds the body itself).
    */
  private[sims] def guardFailure(i: Int, stage: String, checked: Checked): Nothing =
    guardFailed = true // `step` restores the world and rethrows this as it is
    throw ArithmeticException(s"non-finite ${checked.quantity} of body $i (${bodyList(i)}) in phase '$stage'; " +
      "the world was restored to its state before the step")

  /** What a step that failed in `failedStage` with `error` throws (the world restored): the
    * guard's own error as it is (it names body and stage), an error of the virtual machine as it
    * is, a Java platform exception as a new one of its type naming the stage (the original its
    * cause), anything else as a [[StepFailedException]].
    */
  protected def failure(error: Throwable, failedStage: String): Throwable =
    if guardFailed then
      guardFailed = false
      error
    else if !scala.util.control.NonFatal(error) then error
    else
      val message = s"step failed in stage '$failedStage' of ${StepGuard.solverName(solver)}: ${error.getMessage}; " +
        "the world was restored to its state before the step"
      StepGuard.sameKind(error, message).getOrElse(StepFailedException(failedStage, message, error))

  // java.lang.Double.isFinite is static: `d.isNaN` goes through a boxed java.lang.Double.
  private inline def finite(d: Double): Boolean = java.lang.Double.isFinite(d)

/** The world's own stage names and the errors of a failed step. */
private[sims] object StepGuard:
  /** No step under way. */
  val NoStage = "none"
  /** The step has begun, its solver has not named a stage yet. */
  val StartStage = "start of step"
  /** The world's post-step hook (phase 7). */
  val PostStepStage = "post-step hook"
  /** The contact and sensor events, after the solver's stages. */
  val EventsStage = "contact and sensor events"

  /** The solver's name for messages: its class's, without the parameters. */
  def solverName(solver: AnyRef): String = solver.getClass.getSimpleName.stripSuffix("$")

  /** A new exception of `error`'s type with `message` and `error` as its cause, if that type is
    * one of the Java platform's common exceptions (by name, not by reflection, which Scala.js
    * lacks), exactly: a subclass (the user's, or the platform's own) keeps its own type.
    */
  def sameKind(error: Throwable, message: String): Option[Throwable] =
    val made: Throwable = error match
      case _: ArrayIndexOutOfBoundsException => ArrayIndexOutOfBoundsException(message)
      case _: StringIndexOutOfBoundsException => StringIndexOutOfBoundsException(message)
      case _: IndexOutOfBoundsException => IndexOutOfBoundsException(message)
      case _: NumberFormatException => NumberFormatException(message)
      case _: IllegalArgumentException => IllegalArgumentException(message)
      case _: IllegalStateException => IllegalStateException(message)
      case _: ArithmeticException => ArithmeticException(message)
      case _: NullPointerException => NullPointerException(message)
      case _: ClassCastException => ClassCastException(message)
      case _: UnsupportedOperationException => UnsupportedOperationException(message)
      case _: java.util.NoSuchElementException => java.util.NoSuchElementException(message)
      case _: java.util.ConcurrentModificationException => java.util.ConcurrentModificationException(message)
      case _: NegativeArraySizeException => NegativeArraySizeException(message)
      case _: ArrayStoreException => ArrayStoreException(message)
      case _: RuntimeException => RuntimeException(message)
      case _: AssertionError => AssertionError(message)
      case _ => null
    if made == null || made.getClass != error.getClass then None
    else
      made.initCause(error)
      Some(made)
