package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.Defaults
import sims.collision.{Collision, Contact, Detector, GridDetector, RayHit, ShapeQueries}
import sims.dynamics.joints.Joint
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
    this

  /** Adds a joint; fails if it is already in this or another world. Its bodies must be in
    * the world by the next step.
    */
  def +=(joint: Joint): this.type =
    if joint == null then throw IllegalArgumentException("joint must not be null")
    if jointBuffer.exists(_ eq joint) then throw IllegalArgumentException(s"joint $joint is already in this world")
    if joint.world != null then throw IllegalArgumentException(s"joint $joint is already in another world")
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
    this

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

  /** Simulates one time step with the `solver`. If a stage produces a non-finite force,
    * velocity or position, the world is restored to its state before the step and an
    * ArithmeticException names the body and the stage.
    */
  def step(): Unit =
    checkJoints()
    beforeStep.save(this, withSolvers = false)
    startSolverStep()
    shapesMoved()
    _solver.step(this)
    shapesMoved() // also after: a query made during the step (by a joint, say) saw other positions
    postStep()

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
      i += 1

  /** Called by a solver after each stage of a step: throws, after restoring the state before
    * the step, if any body's checked quantity is no longer finite.
    */
  private[sims] def guard(phase: String, checked: Checked): Unit =
    var i = 0
    while i < bodyBuffer.length do
      val b = bodyBuffer(i)
      val ok = checked match
        case Checked.Forces => finite(b.fx) && finite(b.fy) && finite(b.tau)
        case Checked.Velocities => finite(b.vx) && finite(b.vy) && finite(b.w)
        case Checked.Positions => finite(b.x) && finite(b.y) && finite(b.angle)
      if !ok then
        val message = s"non-finite ${checked.quantity} of body $i ($b) in phase '$phase'; the world was restored to its state before the step"
        undoStep()
        throw ArithmeticException(message)
      i += 1

  // java.lang.Double.isFinite is static: `d.isNaN` goes through a boxed java.lang.Double.
  private inline def finite(d: Double): Boolean = java.lang.Double.isFinite(d)

/** Defaults of the world's methods. */
object World:
  /** The queries' default filter: every shape. */
  val AnyShape: Shape => Boolean = _ => true

/** What the world's guard checks after a stage of a step. */
private[sims] enum Checked(val quantity: String):
  case Forces extends Checked("force")
  case Velocities extends Checked("velocity")
  case Positions extends Checked("position")
