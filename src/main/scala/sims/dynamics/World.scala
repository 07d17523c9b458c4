package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.Defaults
import sims.collision.{Collision, Contact, ContactEvents, Detector, GridDetector, PairTracker, RayHit, SensorEvents,
  SensorOverlaps, ShapeQueries}
import sims.dynamics.joints.{Joint, SpringJoint}
import sims.geometry.{AABB, Vector2D}
import sims.solver.{CarriedState, ClassicStep, Solver}

/** A world of bodies and joints, stepped in time by `step()` (documentation chapters 3 and 4).
  *
  * The world keeps the bookkeeping: bodies, joints, shapes, time and settings. What one step
  * does is its `solver`'s: [[sims.solver.ClassicStep]] (SiMS 1.2's step, SPEC section 2) unless
  * another is chosen. The world checks the state after each stage of a step and runs the
  * post-step hook.
  *
  * The collision detector is made by `makeDetector` when the world is created, a
  * [[sims.collision.GridDetector]] unless another is given: `World(MyDetector(_))`. (The
  * documentation's `new World { override val detector = MyDetector(this) }` works too, but
  * builds and drops a grid detector first.)
  */
class World(makeDetector: World => Detector = GridDetector(_)):
  private var _timeStep = Defaults.TimeStep
  private var _iterations = Defaults.Iterations
  private var _gravity = Defaults.Gravity
  private var _time = 0.0
  private var _solver: Solver = ClassicStep
  private val bodyBuffer = ArrayBuffer.empty[Body]
  private val jointBuffer = ArrayBuffer.empty[Joint]
  // All shapes in joining order; the array the detector reads is rebuilt from it only when
  // it is read after a change, so adding n bodies one by one costs O(n), not O(n^2).
  private val shapeList = ArrayBuffer.empty[Shape]
  private var shapeArray = Array.empty[Shape]
  private var shapesChanged = false
  private var nextShapeIndex = 0
  private val beforeStep = WorldState.empty
  // Per-world data of the solvers this world has stepped with (see `workspace`).
  private val workspaces = ArrayBuffer.empty[AnyRef]

  /** The collision detector used by `step()`. */
  val detector: Detector = makeDetector(this)

  // The queries' own broadphase, brought up to date at the first query after a change.
  private val queries = ShapeQueries(this)

  // Contact and sensor events: the pairs touching (overlapping) from step to step, the events
  // of the last step, and the sensor shapes (counted as they join, leave and change their flag;
  // listed in world order when the sensor stage next needs them).
  private[sims] val contactTracker = PairTracker(ordered = false)
  private[sims] val sensorTracker = PairTracker(ordered = true)
  private val contactLog = ContactEvents(contactTracker)
  private val sensorLog = SensorEvents(sensorTracker)
  private val sensorOverlaps = SensorOverlaps()
  private val sensorList = ArrayBuffer.empty[Shape]
  private var sensorCount = 0
  private var sensorListStale = false

  /** Number of bullets (`Body.bullet`) among the bodies: the steps sweep them when it is not 0. */
  private[sims] var bulletCount: Int = 0

  /** Whether collisions are detected and corrected. */
  var enableCollisionDetection: Boolean = true

  /** Whether phase 6 (position correction) runs. */
  var enablePositionCorrection: Boolean = true

  /** What `step()` runs (default [[sims.solver.ClassicStep]]); may be switched at any time. */
  def solver: Solver = _solver

  /** Chooses the solver of the next steps; must not be null. */
  def solver_=(value: Solver): Unit =
    if value == null then throw IllegalArgumentException("solver must not be null")
    _solver = value

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
  private[sims] def shapeBuffer: Array[Shape] =
    // A new array each time the shapes change: views handed out by `shapes` stay as they were.
    if shapesChanged then
      shapeArray = shapeList.toArray
      shapesChanged = false
    shapeArray

  /** The collisions the detector found last (in the classic step: after the last position
    * correction of the last step), e.g. to draw them. The objects are the detector's own: the
    * built-in detector refills them in place at its next `detect()` or `refresh()`, so they
    * describe the last step until the next `step()`; copy what you need to keep.
    */
  def collisions: collection.IndexedSeq[Collision] = detector.collisions

  /** The contacts of the last step as its solver saw them (for either step: the classic
    * step's collisions, the soft step's manifolds with their impulses), as copies that stay
    * valid.
    */
  def contacts: IndexedSeq[Contact] = _solver.contacts(this)

  /** The contact events of the last step: the pairs of shapes that began to touch and those
    * that stopped, every begin followed by exactly one end in a later step (see
    * [[sims.collision.ContactEvents]]); valid until the next step.
    */
  def contactEvents: ContactEvents = contactLog

  /** The sensor events of the last step: the shapes that began and stopped overlapping a sensor
    * shape (`Shape.sensor`), paired like contact events (see [[sims.collision.SensorEvents]]).
    */
  def sensorEvents: SensorEvents = sensorLog

  /** The nearest shape that the straight path from `from` to `to` enters, among those `filter`
    * accepts (all by default), with where and at what fraction of the way; None if it enters
    * none. Shapes it starts inside are not hit; a user's shape kind is hit only if its class
    * overrides `Shape.rayCast`. Looks at the shapes near the path only (through a grid).
    */
  def rayCast(from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape): Option[RayHit] =
    queries.rayCast(Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to), requireFilter(filter))

  /** Every shape the path from `from` to `to` enters, as `rayCast` finds them, nearest first
    * (shapes hit at the same fraction in the order they joined the world).
    */
  def rayCastAll(from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape): IndexedSeq[RayHit] =
    queries.rayCastAll(Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to), requireFilter(filter))

  /** The shapes whose bounding boxes overlap (or touch) `box`, among those `filter` accepts, in
    * the order they joined the world. Looks at the shapes near the box only.
    */
  def query(box: AABB, filter: Shape => Boolean = World.AnyShape): IndexedSeq[Shape] =
    if box == null then throw IllegalArgumentException("box must not be null")
    Vector2D.requireFinite("box.minVertex", box.minVertex)
    Vector2D.requireFinite("box.maxVertex", box.maxVertex)
    if box.minVertex.x > box.maxVertex.x || box.minVertex.y > box.maxVertex.y then
      throw IllegalArgumentException(s"box must have its minVertex below and left of its maxVertex, got $box")
    queries.query(box.minVertex.x, box.minVertex.y, box.maxVertex.x, box.maxVertex.y, requireFilter(filter))

  /** The shapes that contain `point` (world coordinates), among those `filter` accepts, in the
    * order they joined the world (the viewer picks the last free one).
    */
  def shapesAt(point: Vector2D, filter: Shape => Boolean = World.AnyShape): IndexedSeq[Shape] =
    queries.shapesAt(Vector2D.requireFinite("point", point), requireFilter(filter))

  private def requireFilter(filter: Shape => Boolean): Shape => Boolean =
    if filter == null then throw IllegalArgumentException("filter must not be null")
    filter

  /** Tells the queries that shapes moved, joined or left: they take the bounds again when next asked. */
  private[sims] def shapesMoved(): Unit = queries.stale = true

  /** Adds to `found`, in world order, every shape (collidable or not) whose bounds overlap the
    * box: the query grid's answer, without a filter or a copy (for the library's own stages).
    */
  private[sims] def shapesNear(minX: Double, minY: Double, maxX: Double, maxY: Double,
      found: ArrayBuffer[Shape]): Unit =
    queries.near(minX, minY, maxX, maxY, found)

  /** Called by a shape of this world whose `sensor` flag changed to `value`. */
  private[sims] def sensorChanged(value: Boolean): Unit =
    sensorCount += (if value then 1 else -1)
    sensorListStale = true

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
    for s <- body.shapes do
      s.worldIndex = nextShapeIndex
      nextShapeIndex += 1
    shapeList ++= body.shapes
    shapesChanged = true
    shapesMoved()
    countFlags(body, 1)
    this

  /** Adds a joint; fails if it is already in this or another world. Its bodies must be in
    * the world by the next step.
    */
  def +=(joint: Joint): this.type =
    if joint == null then throw IllegalArgumentException("joint must not be null")
    if jointBuffer.exists(_ eq joint) then throw IllegalArgumentException(s"joint $joint is already in this world")
    if joint.world != null then throw IllegalArgumentException(s"joint $joint is already in another world")
    joint match
      case spring: SpringJoint => checkStability(spring, IllegalArgumentException(_))
      case _ => ()
    jointBuffer += joint
    joint.world = this
    if !joint.collideConnected then joint.keepApart(true)
    this

  /** Removes a body (joints on it must be removed too before the next step). */
  def -=(body: Body): this.type =
    val i = bodyBuffer.indexWhere(_ eq body)
    if i >= 0 then
      bodyBuffer.remove(i)
      body.world = null
      body.index = -1
      body.shapes.foreach(_.worldIndex = -1)
      // The later bodies move down one place: their indices follow.
      for j <- i until bodyBuffer.length do bodyBuffer(j).index = j
      shapeList.filterInPlace(_.body ne body)
      shapesChanged = true
      shapesMoved()
      countFlags(body, -1)
    this

  /** Counts the sensors and the bullet of a body joining (`sign` 1) or leaving (-1). */
  private def countFlags(body: Body, sign: Int): Unit =
    if body.bullet then bulletCount += sign
    val sensors = body.shapes.count(_.sensor)
    if sensors > 0 then
      sensorCount += sign * sensors
      sensorListStale = true

  /** Removes a joint. */
  def -=(joint: Joint): this.type =
    val i = jointBuffer.indexWhere(_ eq joint)
    if i >= 0 then
      jointBuffer.remove(i)
      joint.world = null
      if !joint.collideConnected then joint.keepApart(false)
    this

  /** Run after each step (phase 7); override it to observe or steer the simulation. */
  def postStep(): Unit = ()

  /** Simulates one time step with the `solver`, then runs `postStep()`.
    *
    * A step either completes or changes nothing: if any stage throws, the world (bodies, time,
    * joints' impulses, the solvers' carried contacts) is restored to its state before the step
    * and the error names the stage. A non-finite force, velocity or position is an
    * ArithmeticException naming the body and the stage. Any other exception of a Java platform
    * type (an IllegalStateException for a shape pair no narrowphase method covers, say) is
    * rethrown as a new exception of the same type whose message names the stage and whose cause
    * is the original; an exception of another type (a user's own, from a detection method or
    * the post-step hook) as a [[StepFailedException]] with the original as its cause. Errors of
    * the virtual machine (out of memory) are rethrown as they are, after trying to restore.
    */
  def step(): Unit =
    checkJoints()
    beforeStep.save(this, withSolvers = false)
    startSolverStep()
    startEvents()
    shapesMoved()
    stage = World.StartStage
    try
      _solver.step(this)
      shapesMoved() // also after: a query made during the step (by a joint, say) saw other positions
      stage = World.EventsStage
      finishEvents()
      stage = World.PostStepStage
      postStep()
    catch case error: Throwable => failStep(error)
    shapesMoved() // the hook may have moved bodies after a query of its own
    stage = World.NoStage

  /** The stage of the step under way, set by the solver as each stage begins (a constant
    * string, so setting it allocates nothing); named by the error of a failed step.
    */
  private[sims] var stage: String = World.NoStage

  // Set by `guard` when it throws: its exception already names the body and the stage.
  private var guardFailed = false

  /** Restores the state before the step and throws `error`, or an exception naming the stage. */
  private def failStep(error: Throwable): Nothing =
    val failedStage = stage
    stage = World.NoStage
    try undoStep()
    catch case undoError: Throwable => error.addSuppressed(undoError)
    shapesMoved()
    if guardFailed then
      guardFailed = false
      throw error
    if !scala.util.control.NonFatal(error) then throw error
    val message = s"step failed in stage '$failedStage' of ${World.solverName(_solver)}: ${error.getMessage}; " +
      "the world was restored to its state before the step"
    throw World.sameKind(error, message).getOrElse(StepFailedException(failedStage, message, error))

  /** Starts the step's events: nothing touched yet. */
  private def startEvents(): Unit =
    contactTracker.beginStep()
    sensorTracker.beginStep()

  /** The events of the step just solved: the pairs the solver found touching (a solver of the
    * library reports them as it goes; another one's are taken from its `contacts`), the sensors'
    * overlaps, then the begins and ends of both.
    */
  private def finishEvents(): Unit =
    if !_solver.reportsTouching then reportContacts()
    contactTracker.finishStep(this)
    if sensorCount > 0 then
      if sensorListStale then
        sensorList.clear()
        shapeList.foreach(s => if s.sensor then sensorList += s)
        sensorListStale = false
      sensorOverlaps.find(this, sensorList, sensorTracker)
    sensorTracker.finishStep(this)

  /** The touching contacts of a solver that does not report them itself: every contact of its
    * `contacts` with a point at or below zero separation.
    */
  private def reportContacts(): Unit =
    for c <- _solver.contacts(this) if c.touching do
      if contactTracker.touch(c.shape1, c.shape2) then
        val n = c.points.length
        contactTracker.describe(c.normal.x, c.normal.y, c.points.map(_.x).sum / n, c.points.map(_.y).sum / n, 0,
          c.normalImpulses.sum)

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

  /** Makes the pairs of a snapshot the open pairs of the contact and sensor events; the events
    * shown are forgotten.
    */
  private[sims] def restoreEvents(touching: PairTracker.Saved, overlapping: PairTracker.Saved): Unit =
    contactTracker.restoreOpen(touching)
    sensorTracker.restoreOpen(overlapping)

  /** The bodies, for the solvers' loops (not to be modified). */
  private[sims] def bodyList: ArrayBuffer[Body] = bodyBuffer

  /** The joints, for the solvers' loops (not to be modified). */
  private[sims] def jointList: ArrayBuffer[Joint] = jointBuffer

  /** This world's data of one kind of solver (its scratch arrays, its contact table), made by
    * `create` the first time the world steps with a solver of that kind and kept while the
    * world lives, so switching solvers back and forth keeps each one's data.
    */
  private[sims] def workspace[W <: AnyRef](kind: Class[W], create: => W): W =
    var i = 0
    while i < workspaces.length && !kind.isInstance(workspaces(i)) do i += 1
    if i < workspaces.length then workspaces(i).asInstanceOf[W]
    else
      val made = create
      workspaces += made
      made

  /** The solvers' data that steps hand on (see [[sims.solver.CarriedState]]), in the order the
    * world made them.
    */
  private[sims] def carriedStates: collection.IndexedSeq[CarriedState] =
    workspaces.collect { case c: CarriedState => c }

  private def startSolverStep(): Unit =
    var i = 0
    while i < workspaces.length do
      workspaces(i) match
        case c: CarriedState => c.beginStep()
        case _ => ()
      i += 1

  /** Puts the world back as it was before the step under way: bodies, time, joints' impulses and
    * the solvers' carried data.
    */
  private def undoStep(): Unit =
    beforeStep.load(this)
    contactTracker.undoStep()
    sensorTracker.undoStep()
    var i = 0
    while i < workspaces.length do
      workspaces(i) match
        case c: CarriedState => c.undoStep()
        case _ => ()
      i += 1

  private def checkJoints(): Unit =
    var i = 0
    while i < jointBuffer.length do
      val j = jointBuffer(i)
      if !j.bodiesIn(this) then
        throw IllegalArgumentException(s"joint $j connects a body that is not in this world")
      j match
        case spring: SpringJoint => checkStability(spring, IllegalStateException(_)) // h or masses may have changed
        case _ => ()
      i += 1

  /** Fails with `error` unless `spring` is stable over the solver's force interval: a spring too
    * stiff for it grows without bound, to 1e150 m and beyond before any value overflows, so the
    * state a failed step would restore is ruined already.
    */
  private def checkStability(spring: SpringJoint, error: String => RuntimeException): Unit =
    val h = _solver.forceInterval(this)
    val number = spring.stabilityNumber(h)
    if !(number < World.SpringStabilityLimit) then
      throw error(s"$spring is too stiff for the time step: (k h^2 + 2 c h) / m = $number with " +
        s"h = $h s (${World.solverName(_solver)}'s force interval) and c = ${spring.damping} N s/m; " +
        s"springs integrated explicitly diverge from ${World.SpringStabilityLimit} on. Lower springConstant or " +
        "damping, make the bodies heavier or shorten the time step (or, with SoftStep, use more substeps)")

  /** Called by a solver after each stage of a step: throws if any body's checked quantity is no
    * longer finite (`step` then restores the state before the step).
    */
  private[sims] def guard(phase: String, checked: Checked): Unit =
    var i = 0
    while i < bodyBuffer.length do
      val b = bodyBuffer(i)
      val ok = checked match
        case Checked.Forces => finite(b.fx) && finite(b.fy) && finite(b.tau)
        case Checked.Velocities => finite(b.vx) && finite(b.vy) && finite(b.w)
        case Checked.Positions => finite(b.x) && finite(b.y) && finite(b.angle)
      if !ok then guardFailure(i, phase, checked)
      i += 1

  /** The guard for a solver that keeps the bodies' state in an array during the step: body i's
    * checked quantity is `values(i * stride)` to `values(i * stride + 2)`.
    */
  private[sims] def guard(phase: String, checked: Checked, values: Array[Double], stride: Int): Unit =
    var i = 0
    while i < bodyBuffer.length do
      val k = i * stride
      if !(finite(values(k)) && finite(values(k + 1)) && finite(values(k + 2))) then guardFailure(i, phase, checked)
      i += 1

  private def guardFailure(i: Int, phase: String, checked: Checked): Nothing =
    guardFailed = true // `step` restores the world and rethrows this as it is
    throw ArithmeticException(s"non-finite ${checked.quantity} of body $i (${bodyBuffer(i)}) in phase '$phase'; " +
      "the world was restored to its state before the step")

  // java.lang.Double.isFinite is static: `d.isNaN` goes through a boxed java.lang.Double.
  private inline def finite(d: Double): Boolean = java.lang.Double.isFinite(d)

  /** The world in a line: its time, how many bodies and joints it has, and its solver. */
  override def toString: String =
    s"World(time = $time s, ${bodyBuffer.size} bodies, ${jointBuffer.size} joints, solver = ${_solver})"

/** The world's own stage names, the helpers of `World.step`'s errors and the queries' defaults. */
object World:
  /** The queries' default filter: every shape. */
  val AnyShape: Shape => Boolean = _ => true

  /** No step under way. */
  private[sims] val NoStage = "none"
  /** The step has begun, its solver has not named a stage yet. */
  private[sims] val StartStage = "start of step"
  /** Springs whose stability number (`SpringJoint.stabilityNumber`) reaches this diverge. */
  private[sims] val SpringStabilityLimit = 4.0

  /** The world's post-step hook (phase 7). */
  private[sims] val PostStepStage = "post-step hook"

  /** The contact and sensor events, after the solver's stages. */
  private[sims] val EventsStage = "contact and sensor events"

  /** The solver's name for messages: its class's, without the parameters. */
  private[sims] def solverName(solver: Solver): String = solver.getClass.getSimpleName.stripSuffix("$")

  /** A new exception of `error`'s type with `message` and `error` as its cause, if that type is
    * one of the Java platform's and has a constructor taking a message.
    */
  private[sims] def sameKind(error: Throwable, message: String): Option[Throwable] =
    if !error.getClass.getName.startsWith("java.") then None
    else
      try
        val made = error.getClass.getConstructor(classOf[String]).newInstance(message)
        made.initCause(error)
        Some(made)
      catch case _: ReflectiveOperationException | _: IllegalStateException | _: SecurityException => None

/** What the world's guard checks after a stage of a step. */
private[sims] enum Checked(val quantity: String):
  case Forces extends Checked("force")
  case Velocities extends Checked("velocity")
  case Positions extends Checked("position")
