package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.Defaults
import sims.collision.{CollisionPipeline, Detector, GridDetector}
import sims.dynamics.joints.Joint
import sims.geometry.Vector2D

/** A world of bodies and joints, stepped in time by `step()` (documentation chapters 3 and 4).
  *
  * The world coordinates: it keeps the bodies, joints and shapes, the settings and the time,
  * and runs each step as a transaction (see `step`). What one step does is its `solver`'s:
  * [[sims.solver.ClassicStep]] (SiMS 1.2's step) unless another is chosen ([[SolverChoice]]). Its queries
  * ([[WorldQueries]]), its contact and sensor events ([[WorldEvents]]), the guard a solver calls
  * after each stage ([[StepGuard]]), the solvers' own data ([[SolverWorkspaces]]), sleeping
  * ([[WorldSleep]]) and the joints that break ([[JointBreaking]]) each have a file of their own.
  *
  * The collision detector is made by `makeDetector` when the world is created, a
  * [[sims.collision.GridDetector]] unless another is given: `World(MyDetector(_))`. (The
  * documentation's `new World { override val detector = MyDetector(this) }` works too, but
  * builds and drops a grid detector first.)
  */
class World(makeDetector: World => Detector = GridDetector(_))
    extends SolverChoice, WorldQueries, WorldEvents, StepGuard, SolverWorkspaces, WorldSleep, JointBreaking:
  private var _timeStep = Defaults.TimeStep
  private var _iterations = Defaults.Iterations
  private var _gravity = Defaults.Gravity
  private var _time = 0.0
  private val bodyBuffer = ArrayBuffer.empty[Body]
  private val jointBuffer = ArrayBuffer.empty[Joint]
  private val shapeList = ShapeList()
  private[sims] val stateBeforeStep = WorldState.empty // the step's own save (see Solver.savesBodies)

  /** The world's one broadphase, list of candidate pairs and narrowphase, shared by both steps
    * and the queries (made before the detector, which uses them).
    */
  private[sims] val collisionPipeline: CollisionPipeline = CollisionPipeline()

  /** The collision detector used by `step()`. */
  val detector: Detector = makeDetector(this)

  /** Number of bullets (`Body.bullet`) among the bodies: the steps sweep them when it is not 0. */
  private[sims] var bulletCount: Int = 0

  /** Whether collisions are detected and corrected. */
  var enableCollisionDetection: Boolean = true

  /** Whether phase 6 (position correction) runs. */
  var enablePositionCorrection: Boolean = true

  /** Duration of one step in seconds (default 1/60). */
  def timeStep: Double = _timeStep

  /** Sets the step duration; must be positive and finite. */
  def timeStep_=(h: Double): Unit = _timeStep = Shape.requirePositive("timeStep", h)

  /** Number of velocity and of position correction iterations per step of the classic step
    * (default 10).
    */
  def iterations: Int = _iterations

  /** Sets the number of iterations; must be at least 1. */
  def iterations_=(n: Int): Unit =
    if n < 1 then throw IllegalArgumentException(s"iterations must be at least 1, got $n")
    _iterations = n

  /** Acceleration of gravity in m/s^2 (default (0, -9.81)). */
  def gravity: Vector2D = _gravity

  /** Sets gravity; must be finite. */
  def gravity_=(g: Vector2D): Unit = _gravity = Vector2D.requireFinite("gravity", g)

  /** Simulated time in seconds: the number of steps so far times their durations. */
  def time: Double = _time

  /** The bodies of this world, in the order they were added. */
  def bodies: collection.IndexedSeq[Body] = bodyBuffer

  /** The joints of this world, in the order they were added. */
  def joints: collection.IndexedSeq[Joint] = jointBuffer

  /** All shapes of all bodies, in the order they joined the world. */
  def shapes: IndexedSeq[Shape] = collection.immutable.ArraySeq.unsafeWrapArray(shapeBuffer)

  /** Shapes as an array for the detector (not to be modified). */
  private[sims] def shapeBuffer: Array[Shape] = shapeList.array

  /** The bodies, for the solvers' loops (not to be modified). */
  private[sims] def bodyList: ArrayBuffer[Body] = bodyBuffer

  /** The joints, for the solvers' loops (not to be modified). */
  private[sims] def jointList: ArrayBuffer[Joint] = jointBuffer

  /** Called by a body of this world whose `bullet` flag changed to `value`. */
  private[sims] def bulletChanged(value: Boolean): Unit = bulletCount += (if value then 1 else -1)

  /** Adds a body; fails if it is already in this or another world. */
  def +=(body: Body): this.type =
    if body == null then throw IllegalArgumentException("body must not be null")
    if body.world eq this then throw IllegalArgumentException(s"body $body is already in this world")
    if body.world != null then throw IllegalArgumentException(s"body $body is already in another world")
    body.world = this
    body.index = bodyBuffer.length
    bodyBuffer += body
    bodyIds.register(body)
    shapeList.add(body)
    shapesMoved()
    countFlags(body, 1)
    revision += 1
    // A body put to sleep outside a world sleeps in an island of its own.
    if !body.isAwake && body.sleepIsland == Long.MaxValue then body.sleepIsland = newSleepIsland()
    this

  /** Adds a joint; fails if it is already in this or another world, or if the solver cannot
    * step it (a spring too stiff for the time step). Its bodies must be in the world by the
    * next step.
    */
  def +=(joint: Joint): this.type =
    if joint == null then throw IllegalArgumentException("joint must not be null")
    if joint.world eq this then throw IllegalArgumentException(s"joint $joint is already in this world")
    if joint.world != null then throw IllegalArgumentException(s"joint $joint is already in another world")
    forceIntervalProblem(joint).foreach(problem => throw IllegalArgumentException(problem))
    classicProblem(joint).foreach(problem => throw IllegalArgumentException(problem))
    jointBuffer += joint
    joint.world = this
    if !joint.collideConnected then joint.keepApart(true)
    joint.node1.wake(); joint.node2.wake()
    revision += 1
    this

  /** Removes a body (joints on it must be removed too before the next step). */
  def -=(body: Body): this.type =
    val i = if body != null && (body.world eq this) then body.index else -1
    if i >= 0 then
      // Its island wakes (a body asleep on it would hang in the air); a fixed body may have held any island up: all wake.
      if body.fixed then wakeAll() else body.wake()
      revision += 1
      bodyBuffer.remove(i)
      bodyIds.unregister(body)
      body.world = null
      body.index = -1
      // The later bodies move down one place: their indices follow.
      var j = i
      while j < bodyBuffer.length do { bodyBuffer(j).index = j; j += 1 }
      shapeList.remove(body)
      shapesMoved()
      countFlags(body, -1)
    this

  /** Removes a joint. */
  def -=(joint: Joint): this.type =
    val i = jointBuffer.indexWhere(_ eq joint)
    if i >= 0 then removeJointAt(i)
    this

  private[dynamics] def removeJointAt(i: Int): Unit =
    val joint = jointBuffer.remove(i)
    joint.node1.wake(); joint.node2.wake()
    revision += 1
    joint.world = null
    if !joint.collideConnected then joint.keepApart(false)

  /** Counts the sensors and the bullet of a body joining (`sign` 1) or leaving (-1). */
  private def countFlags(body: Body, sign: Int): Unit =
    if body.bullet then bulletCount += sign
    countSensors(body, sign)

  /** Run after each step (phase 7); override it to observe or steer the simulation. */
  def postStep(): Unit = ()

  /** Simulates one time step with the `solver`, then runs `postStep()`.
    *
    * A step either completes or changes nothing: if any stage throws, the world (bodies, time,
    * the solvers' carried data: the soft step's contacts and joints' impulses) is restored to
    * its state before the step and the error names the stage. A non-finite force, velocity or
    * position is an ArithmeticException naming the body and the stage. Any other exception of a
    * Java platform type (an IllegalStateException for a shape pair no narrowphase method covers,
    * say) is rethrown as a new exception of the same type whose message names the stage and
    * whose cause is the original; an exception of another type (a user's own, from a detection
    * method or the post-step hook) as a [[StepFailedException]] with the original as its cause.
    * Errors of the virtual machine (out of memory) are rethrown as they are, after trying to
    * restore.
    */
  def step(): Unit =
    checkJoints()
    stateBeforeStep.saveForStep(this)
    beginCarriedStates()
    startEvents()
    shapesMoved()
    enterStage(StepGuard.StartStage)
    try
      solver.step(this)
      shapesMoved() // also after: a query made during the step (by a joint, say) saw other positions
      enterStage(StepGuard.EventsStage)
      breakJoints()
      finishEvents()
      enterStage(StepGuard.PostStepStage)
      postStep()
    catch case error: Throwable => failStep(error)
    shapesMoved() // the hook may have moved bodies after a query of its own
    enterStage(StepGuard.NoStage)

  /** Advances the time by one `timeStep`; for solvers, once per step, during `step()` only. */
  def advanceTime(): Unit =
    requireStep("advanceTime")
    _time += _timeStep

  /** Restores the state before the step and throws `error`, or an exception naming the stage. */
  private def failStep(error: Throwable): Nothing =
    val failedStage = stage
    enterStage(StepGuard.NoStage)
    try undoStep()
    catch case undoError: Throwable => error.addSuppressed(undoError)
    shapesMoved()
    throw failure(error, failedStage)

  /** Puts the world back as it was before the step under way: bodies, time, the events' open
    * pairs and the solvers' carried data.
    */
  private def undoStep(): Unit =
    unbreakJoints() // first: the saved state is of the joints before the step
    stateBeforeStep.load(this)
    undoEvents()
    undoCarriedStates()

  /** A copy of the dynamic state of every body and of the time, to `restore` later. */
  def snapshot(): WorldState =
    val state = WorldState.empty
    state.save(this)
    state

  /** Puts the world back into a state taken by `snapshot()`; the bodies must be the same. */
  def restore(state: WorldState): Unit =
    state.load(this)
    shapesMoved()

  private[sims] def time_=(t: Double): Unit = _time = t

  /** The world by its counts, time and solver, e.g.
    * `World(bodies = 3, joints = 1, shapes = 4, time = 0.5 s, solver = ClassicStep)`.
    */
  override def toString: String =
    s"World(bodies = ${bodyBuffer.length}, joints = ${jointBuffer.length}, shapes = ${shapeList.array.length}, " +
      s"time = ${_time} s, solver = $solver)"

/** The queries' default filter. */
object World:
  /** The queries' default filter: every shape. */
  val AnyShape: Shape => Boolean = _ => true
