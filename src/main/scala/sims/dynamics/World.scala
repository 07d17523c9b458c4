package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.collision.{Collision, Detector, GridDetector}
import sims.dynamics.joints.{ForceJoint, Joint}
import sims.geometry.Vector2D

/** A world of bodies and joints, stepped in time by `step()` (documentation chapters 3 and 4).
  *
  * The collision detector is `GridDetector(this)` unless replaced when the world is created:
  * `new World { override val detector = MyDetector(this) }` (documentation 5.3).
  */
class World:
  private var _timeStep = World.DefaultTimeStep
  private var _iterations = World.DefaultIterations
  private var _gravity = World.DefaultGravity
  private var _time = 0.0
  private val bodyBuffer = ArrayBuffer.empty[Body]
  private val jointBuffer = ArrayBuffer.empty[Joint]
  // All shapes in joining order; the array the detector reads is rebuilt from it only when
  // it is read after a change, so adding n bodies one by one costs O(n), not O(n^2).
  private val shapeList = ArrayBuffer.empty[Shape]
  private var shapeArray = Array.empty[Shape]
  private var shapesChanged = false
  private var nextShapeIndex = 0
  private val beforeStep = WorldState.empty
  private val contacts = sims.collision.ContactSolver()

  /** The collision detector used by `step()`. */
  val detector: Detector = GridDetector(this)

  /** Whether collisions are detected and corrected. */
  var enableCollisionDetection: Boolean = true

  /** Whether phase 6 (position correction) runs. */
  var enablePositionCorrection: Boolean = true

  /** Duration of one step in seconds (default 1/60). */
  def timeStep: Double = _timeStep

  /** Sets the step duration; must be positive and finite. */
  def timeStep_=(h: Double): Unit = _timeStep = Shape.requirePositive("timeStep", h)

  /** Number of velocity and of position correction iterations per step (default 10). */
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

  /** The collisions found in the last step (after its last correction), e.g. to draw them. */
  def collisions: collection.IndexedSeq[Collision] = detector.collisions

  /** Adds a body; fails if it is already in this or another world. */
  def +=(body: Body): this.type =
    if body == null then throw IllegalArgumentException("body must not be null")
    if body.world eq this then throw IllegalArgumentException(s"body $body is already in this world")
    if body.world != null then throw IllegalArgumentException(s"body $body is already in another world")
    body.world = this
    bodyBuffer += body
    for s <- body.shapes do
      s.worldIndex = nextShapeIndex
      s.bodyKey = bodyBuffer.length - 1
      nextShapeIndex += 1
    shapeList ++= body.shapes
    shapesChanged = true
    this

  /** Adds a joint; fails if it is already in this world. Its bodies must be in the world
    * by the next step.
    */
  def +=(joint: Joint): this.type =
    if joint == null then throw IllegalArgumentException("joint must not be null")
    if jointBuffer.exists(_ eq joint) then throw IllegalArgumentException(s"joint $joint is already in this world")
    jointBuffer += joint
    this

  /** Removes a body (joints on it must be removed too before the next step). */
  def -=(body: Body): this.type =
    val i = bodyBuffer.indexWhere(_ eq body)
    if i >= 0 then
      bodyBuffer.remove(i)
      body.world = null
      body.shapes.foreach { s => s.worldIndex = -1; s.bodyKey = -1 }
      // The later bodies move down one place: their keys follow, so keys stay 0 until n.
      for j <- i until bodyBuffer.length; s <- bodyBuffer(j).shapes do s.bodyKey = j
      shapeList.filterInPlace(_.body ne body)
      shapesChanged = true
    this

  /** Removes a joint. */
  def -=(joint: Joint): this.type =
    val i = jointBuffer.indexWhere(_ eq joint)
    if i >= 0 then jointBuffer.remove(i)
    this

  /** Run after each step (phase 7); override it to observe or steer the simulation. */
  def postStep(): Unit = ()

  /** Simulates one time step: the phases of SPEC section 2, in order. If a phase produces a
    * non-finite force, velocity or position, the world is restored to its state before the step and
    * an ArithmeticException names the body and the phase.
    */
  def step(): Unit =
    checkJoints()
    beforeStep.save(this)
    val h = _timeStep
    _time += h                       // phase 1
    applyJointForces()               // phase 2
    guard("joint forces", Checked.Forces)
    integrateAccelerations(h)        // phase 3
    guard("integration of accelerations", Checked.Velocities)
    correctVelocities(h)             // phase 4
    guard("velocity correction", Checked.Velocities)
    integrateVelocities(h)           // phase 5
    guard("integration of velocities", Checked.Positions)
    if enablePositionCorrection then
      correctPositions(h)            // phase 6
      guard("position correction", Checked.Positions)
    postStep()                       // phase 7

  /** A copy of the dynamic state of every body and of the time, to `restore` later. */
  def snapshot(): WorldState =
    val state = WorldState.empty
    state.save(this)
    state

  /** Puts the world back into a state taken by `snapshot()`; the bodies must be the same. */
  def restore(state: WorldState): Unit = state.load(this)

  private[sims] def time_=(t: Double): Unit = _time = t

  private def checkJoints(): Unit =
    var i = 0
    while i < jointBuffer.length do
      val j = jointBuffer(i)
      if !j.bodiesIn(this) then
        throw IllegalArgumentException(s"joint $j connects a body that is not in this world")
      i += 1

  private def applyJointForces(): Unit =
    var i = 0
    while i < jointBuffer.length do
      jointBuffer(i) match
        case f: ForceJoint => f.applyForce()
        case _ => ()
      i += 1

  private def integrateAccelerations(h: Double): Unit =
    val gx = _gravity.x
    val gy = _gravity.y
    var i = 0
    while i < bodyBuffer.length do
      val b = bodyBuffer(i)
      if !b.fixed then
        val m = b.mass
        b.fx += gx * m
        b.fy += gy * m
        b.vx += (b.fx / m) * h
        b.vy += (b.fy / m) * h
        b.w += (b.tau / b.I) * h
      i += 1

  private def correctVelocities(h: Double): Unit =
    if enableCollisionDetection then
      detector.detect()
      contacts.load(detector.collisions)
    else contacts.clear()
    var iteration = 0
    while iteration < _iterations do
      var i = 0
      while i < jointBuffer.length do
        jointBuffer(i).correctVelocity(h)
        i += 1
      contacts.correctVelocities(h)
      iteration += 1

  private def integrateVelocities(h: Double): Unit =
    var i = 0
    while i < bodyBuffer.length do
      val b = bodyBuffer(i)
      if math.sqrt(b.vx * b.vx + b.vy * b.vy) < World.SpeedThreshold then
        b.vx = 0; b.vy = 0
      if math.abs(b.w) < World.SpeedThreshold then b.w = 0
      b.displace(b.vx * h, b.vy * h, b.w * h)
      b.fx = 0; b.fy = 0; b.tau = 0
      i += 1

  private def correctPositions(h: Double): Unit =
    var iteration = 0
    while iteration < _iterations do
      var i = 0
      while i < jointBuffer.length do
        jointBuffer(i).correctPosition(h)
        i += 1
      if enableCollisionDetection then
        detector.refresh()
        val collisions = detector.collisions
        i = 0
        while i < collisions.length do
          collisions(i).correctPosition(h)
          i += 1
      iteration += 1

  /** Throws, after restoring the state before the step, if any body is no longer finite. */
  private def guard(phase: String, checked: Checked): Unit =
    var i = 0
    while i < bodyBuffer.length do
      val b = bodyBuffer(i)
      val finite = checked match
        case Checked.Forces => World.finite(b.fx) && World.finite(b.fy) && World.finite(b.tau)
        case Checked.Velocities => World.finite(b.vx) && World.finite(b.vy) && World.finite(b.w)
        case Checked.Positions => World.finite(b.x) && World.finite(b.y) && World.finite(b.angle)
      if !finite then
        val message = s"non-finite ${checked.quantity} of body $i ($b) in phase '$phase'; the world was restored to its state before the step"
        beforeStep.load(this)
        throw ArithmeticException(message)
      i += 1

  /** What a guard checks after a phase. */
  private enum Checked(val quantity: String):
    case Forces extends Checked("force")
    case Velocities extends Checked("velocity")
    case Positions extends Checked("position")

/** Defaults of a new [[World]]. */
object World:
  /** Default time step, s. */
  val DefaultTimeStep: Double = 1.0 / 60
  /** Default number of correction iterations. */
  val DefaultIterations: Int = 10
  /** Default gravity, m/s^2. */
  val DefaultGravity: Vector2D = Vector2D(0, -9.81)
  /** Linear (m/s) and angular (rad/s) speeds below this become exactly 0 in phase 5. */
  val SpeedThreshold: Double = 0.0001

  // java.lang.Double.isFinite is static: `d.isNaN` goes through a boxed java.lang.Double.
  private inline def finite(d: Double): Boolean = java.lang.Double.isFinite(d)
