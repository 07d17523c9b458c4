package sims.solver.soft

import sims.solver.Workers
import sims.solver.soft.SoftBodies.*

/** The soft step's stages that a [[Workers]] set shares out, as tasks made once per world (a
  * step allocates nothing for them): the contacts' warm start and solve pass colour by colour
  * (see [[ContactColours]]), and the per-body and per-contact stages in ranges. Each range writes
  * only its own slots, so the bits do not depend on the number of workers.
  */
private[sims] final class SoftPasses(workspace: SoftWorkspace):
  /** The colours of this step's contacts. */
  val colours: ContactColours = ContactColours()

  // The settings of the pass under way.
  private var inverseH = 0.0
  private var contactSpeed = 0.0
  private var useBias = false
  private var h = 0.0
  private var gx = 0.0
  private var gy = 0.0
  // The first index in `colours.order` of the colour under way.
  private var base = 0

  private val warmStartTask: Workers.Task = (from, until) =>
    ContactConstraints.warmStart(workspace.table.current, workspace.bodies, colours.order, base + from, base + until)

  private val solveTask: Workers.Task = (from, until) =>
    ContactConstraints.solve(workspace.table.current, workspace.bodies, colours.order, base + from, base + until,
      inverseH, contactSpeed, useBias)

  private val prepareTask: Workers.Task = (from, until) =>
    ContactConstraints.prepare(workspace.table.current, workspace.bodies, workspace.stiffness, from, until)

  private val freeMotionTask: Workers.Task = (from, until) =>
    ContactConstraints.addFreeMotion(workspace.table.current, workspace.bodies, gx, gy, h, from, until)

  private val velocitiesTask: Workers.Task = (from, until) => integrateVelocities(from, until)

  private val positionsTask: Workers.Task = (from, until) => integratePositions(from, until)

  /** Colours this step's contacts, then prepares them (effective masses, softness). */
  def prepare(workers: Workers): Unit =
    colours.colour(workspace.table.current, workspace.bodies)
    workers.run(workspace.table.current.active, prepareTask)

  /** Applies the contacts' accumulated impulses, colour by colour. */
  def warmStart(workers: Workers): Unit = byColour(workers, warmStartTask)

  /** One pass over the contacts, with the bias (solve) or without (relax), colour by colour. */
  def solve(workers: Workers, inverseH: Double, contactSpeed: Double, useBias: Boolean): Unit =
    this.inverseH = inverseH
    this.contactSpeed = contactSpeed
    this.useBias = useBias
    byColour(workers, solveTask)

  /** Gravity and forces over a substep h for every moving body, then what they add to the
    * contacts' approach (`ContactConstraints.addFreeMotion`).
    */
  def integrateVelocities(workers: Workers, gx: Double, gy: Double, h: Double): Unit =
    this.gx = gx
    this.gy = gy
    this.h = h
    workers.run(workspace.bodies.count, velocitiesTask)
    workers.run(workspace.table.current.active, freeMotionTask)

  /** Every body's placement over a substep h. */
  def integratePositions(workers: Workers, h: Double): Unit =
    this.h = h
    workers.run(workspace.bodies.count, positionsTask)

  // The colours in turn, each shared out; the overflow on the caller, in its order.
  private def byColour(workers: Workers, task: Workers.Task): Unit =
    var k = 0
    while k < ContactColours.Count do
      val n = colours.colourSize(k)
      if n > 0 then
        base = colours.starts(k)
        workers.run(n, task)
      k += 1
    val overflow = colours.colourSize(ContactColours.Count)
    if overflow > 0 then
      base = colours.starts(ContactColours.Count)
      task.run(0, overflow)

  // v += h (g + F/m), w += h tau/I for the moving bodies from until until.
  private def integrateVelocities(from: Int, until: Int): Unit =
    val bodies = workspace.bodies
    val state = bodies.state
    var i = from
    while i < until do
      val m = bodies.invMass(i)
      if m != 0 then
        val k = i * SoftBodies.Stride
        // Times the gravity scale, 1 unless the user set it: exact, the sums unchanged.
        val scale = bodies.gravityScale(i)
        state(k + VelocityX) += h * (gx * scale + bodies.substepForceX(i) * m)
        state(k + VelocityY) += h * (gy * scale + bodies.substepForceY(i) * m)
        state(k + AngularVelocity) += h * bodies.substepTorque(i) * bodies.invI(i)
        if bodies.anyDamped then
          state(k + VelocityX) *= bodies.linearDecay(i)
          state(k + VelocityY) *= bodies.linearDecay(i)
          state(k + AngularVelocity) *= bodies.angularDecay(i)
      i += 1

  // dp += h v, dAngle += h w and the turn's cosine and sine, for the bodies from until until.
  private def integratePositions(from: Int, until: Int): Unit =
    val state = workspace.bodies.state
    var i = from
    while i < until do
      val k = i * SoftBodies.Stride
      val vx = state(k + VelocityX); val vy = state(k + VelocityY); val w = state(k + AngularVelocity)
      state(k + ShiftX) += h * vx
      state(k + ShiftY) += h * vy
      if w != 0 then
        state(k + Turn) += h * w
        val c = state(k + TurnCos); val s = state(k + TurnSin)
        val turnedC = c - h * w * s
        val turnedS = s + h * w * c
        val length = math.sqrt(turnedC * turnedC + turnedS * turnedS)
        state(k + TurnCos) = turnedC / length
        state(k + TurnSin) = turnedS / length
      i += 1

  override def toString: String = s"SoftPasses($colours)"
