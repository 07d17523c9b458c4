package sims.solver.soft

import sims.solver.Workers
import sims.solver.soft.SoftBodies.*

/** The soft step's stages that a [[Workers]] set shares out, as tasks made once per world (a
  * step allocates nothing for them): the contacts' preparation and the bodies' integration in
  * ranges, the contacts' warm start and passes block by block, level by level (see
  * [[ContactBlocks]]). Every task writes slots of its own (a range's contacts or bodies, a block
  * that shares no moving body with the others of its level), so the bits do not depend on the
  * number of workers.
  */
private[sims] final class SoftPasses(workspace: SoftWorkspace):
  /** The order of this step's contacts, in blocks. */
  val blocks: ContactBlocks = ContactBlocks()

  // The settings of the stage under way.
  private var inverseH, contactSpeed, h, gx, gy = 0.0
  private var useBias = false
  private var level = 0
  // The stage under way covers this many items in this many ranges.
  private var items, ranges = 1

  private val prepareTask: Workers.Task = index =>
    ContactConstraints.prepare(workspace.table.current, workspace.bodies, workspace.stiffness, from(index),
      from(index + 1))

  private val warmStartTask: Workers.Task = index =>
    val block = blocks.levelStart(level) + index
    ContactConstraints.warmStart(workspace.table.current, workspace.bodies, blocks, blocks.start(block),
      blocks.start(block + 1))

  private val solveTask: Workers.Task = index =>
    val block = blocks.levelStart(level) + index
    ContactConstraints.solve(workspace.table.current, workspace.bodies, blocks, blocks.start(block),
      blocks.start(block + 1), inverseH, contactSpeed, useBias)

  private val velocitiesTask: Workers.Task = index =>
    integrateVelocities(from(index), from(index + 1))
    if checking then
      rangeResults(index) = if workspace.bodies.finiteMotion(from(index), from(index + 1)) then 0 else 1

  // Whether `integrateVelocities` checks the forces and velocities it leaves.
  private var checking = false

  private val positionsTask: Workers.Task = index => integratePositions(from(index), from(index + 1))

  // The bodies' list being loaded, and per range what `SoftBodies.loadRange` or `finishRange` found.
  private var list: scala.collection.mutable.ArrayBuffer[sims.dynamics.Body] = null
  private var saved: sims.dynamics.WorldState = null
  private var rangeResults = new Array[Int](1)

  private val loadTask: Workers.Task = index =>
    rangeResults(index) = workspace.bodies.loadRange(list, saved, h, from(index), from(index + 1))

  // The world whose step is ending (see `finish`, `close` and `settleEvents`).
  private var closing: sims.dynamics.World = null

  private val closeTask: Workers.Task = index =>
    val world = closing
    index match
      case 0 =>
        if world.enableContactEvents then
          ContactTouching.report(workspace.table.current, workspace.bodies, world.contactTracker, touchingPoints)
      case 1 => workspace.table.indexCurrent()
      case _ => if readyToSleep then workspace.islands.sleep(world, workspace.bodies, workspace.table.current, world.jointList)

  private val finishTask: Workers.Task = index =>
    val finite = workspace.bodies.finishRange(from(index), from(index + 1))
    // The resting times while the range's bodies are in this core's cache.
    val ready = workspace.islands.rest(closing, workspace.bodies, from(index), from(index + 1))
    rangeResults(index) = (if finite then 0 else SoftPasses.NotFinite) | (if ready then SoftPasses.ReadyToSleep else 0)

  // Whether a body of the step's `finish` has rested long enough to sleep.
  private var readyToSleep = false

  // Per contact: its touching points, for the contact events (see ContactTouching).
  private var touchingPoints = new Array[Int](0)

  private val touchingTask: Workers.Task = index =>
    ContactTouching.measure(workspace.table.current, workspace.bodies, touchingPoints, from(index), from(index + 1))

  /** Prepares this step's contacts (inverse masses, effective masses, softness), then cuts them
    * into blocks, under gravity `(gx, gy)`.
    */
  def prepare(workers: Workers, gx: Double, gy: Double): Unit =
    val contacts = workspace.table.current
    inRanges(workers, contacts.active, prepareTask)
    blocks.split(contacts, workspace.bodies, gx, gy, workers)

  /** Applies the contacts' accumulated impulses, block by block. */
  def warmStart(workers: Workers): Unit = byLevel(workers, warmStartTask)

  /** One pass over the contacts, with the bias (solve) or without (relax), block by block. */
  def solve(workers: Workers, inverseH: Double, contactSpeed: Double, useBias: Boolean): Unit =
    this.inverseH = inverseH
    this.contactSpeed = contactSpeed
    this.useBias = useBias
    byLevel(workers, solveTask)

  /** Gravity and forces over a substep h for every moving body: v += h (g + F/m), w += h tau/I.
    * With `check`, returns whether every body's forces and velocities are finite after it (see
    * [[SoftBodies.finiteMotion]]); otherwise true.
    */
  def integrateVelocities(workers: Workers, gx: Double, gy: Double, h: Double, check: Boolean): Boolean =
    this.gx = gx
    this.gy = gy
    this.h = h
    checking = check
    inRanges(workers, workspace.bodies.count, velocitiesTask)
    checking = false
    !check || rangeFlags == 0

  /** Measures this step's touching contacts for the contact events (see [[ContactTouching]]), in
    * ranges: the workers take the contacts' blocks from the caches of the cores that solved them,
    * not one by one into the caller's. `close` reports them.
    */
  private def measureTouching(workers: Workers): Unit =
    val contacts = workspace.table.current
    if touchingPoints.length < contacts.count then touchingPoints = new Array[Int](2 * contacts.count)
    inRanges(workers, contacts.count, touchingTask)

  /** Takes the state of the bodies of `list` at the start of a step of substeps `h`, in ranges,
    * and saves it into `saved` (see [[SoftBodies.loadRange]]).
    */
  def load(workers: Workers, list: scala.collection.mutable.ArrayBuffer[sims.dynamics.Body],
      saved: sims.dynamics.WorldState, h: Double): Unit =
    val bodies = workspace.bodies
    bodies.begin(list)
    this.list = list
    this.saved = saved
    this.h = h
    try inRanges(workers, bodies.count, loadTask)
    finally
      this.list = null
      this.saved = null
    saved.bodiesSaved()
    bodies.loaded(rangeFlags)

  /** Writes the bodies back at the end of `world`'s step, in ranges (see
    * [[SoftBodies.finishRange]]), and brings their resting times up to date
    * ([[SleepIslands.rest]]); whether every body's velocities and placement are finite.
    */
  def finish(workers: Workers, world: sims.dynamics.World): Boolean =
    closing = world
    try inRanges(workers, workspace.bodies.count, finishTask)
    finally closing = null
    val flags = rangeFlags
    readyToSleep = (flags & SoftPasses.ReadyToSleep) != 0
    (flags & SoftPasses.NotFinite) == 0

  // What the ranges of the stage just run found, their `rangeResults` or-ed together.
  private def rangeFlags: Int =
    var flags = 0
    var r = 0
    while r < ranges do
      flags |= rangeResults(r)
      r += 1
    flags

  /** The step's last work on its contacts: with `world`'s contact events on, the touching
    * contacts measured in ranges; then three tasks at once, which read the contacts and write
    * apart: the touching contacts reported to the events (in contact order), the index of this
    * step's contacts for the next step's lookups ([[ContactTable.indexCurrent]]), and, if a body
    * rested long enough in `finish`, the islands put to sleep (the bodies' sleep fields).
    */
  def close(workers: Workers, world: sims.dynamics.World): Unit =
    if world.enableContactEvents then measureTouching(workers)
    closing = world
    try workers.run(3, closeTask)
    finally closing = null

  /** Ends the step's contact events of `world` (see [[sims.collision.PairTracker.finishStep]]),
    * the open pairs not touched judged in ranges when there are many: every shape's caches made
    * current first, in ranges of shapes (what the judging reads, and what the next step's
    * collision stage would make current anyway), so that no range writes a shape.
    */
  def settleEvents(workers: Workers, world: sims.dynamics.World): Unit =
    val tracker = world.contactTracker
    val count = tracker.beginFinish()
    val shared = workers.count > 1 && count >= SoftPasses.MinimumShared
    val needed = if shared then SoftPasses.RangesPerWorker * workers.count else 1
    if separations.length < needed then separations = Array.fill(needed)(sims.collision.ShapeSeparation())
    if !shared then tracker.judge(world, 0, count, separations(0))
    else
      closing = world
      refreshing = world.shapeBuffer
      try
        inRanges(workers, refreshing.length, refreshTask)
        inRanges(workers, count, judgeTask)
      finally
        closing = null
        refreshing = null
    tracker.endFinish()

  // Per range of `settleEvents`: a separation of its own; the shapes whose caches it refreshes.
  private var separations = new Array[sims.collision.ShapeSeparation](0)
  private var refreshing: Array[sims.dynamics.Shape] = null

  private val refreshTask: Workers.Task = index =>
    sims.dynamics.Shape.refreshCaches(refreshing, from(index), from(index + 1))

  // Blocks of items dealt out to the ranges in turn, not one stretch each: the pairs to judge are
  // those kept open untouched last step, at the list's end, and a stretch each would leave them
  // to one or two ranges while the others found nothing to do.
  private val judgeTask: Workers.Task = index =>
    var start = index * SoftPasses.JudgedBlock
    while start < items do
      closing.contactTracker.judge(closing, start, math.min(start + SoftPasses.JudgedBlock, items), separations(index))
      start += ranges * SoftPasses.JudgedBlock

  /** Every body's placement over a substep h (see `integratePositions` below). */
  def integratePositions(workers: Workers, h: Double): Unit =
    this.h = h
    inRanges(workers, workspace.bodies.count, positionsTask)

  // The levels in turn, each level's blocks shared out.
  private def byLevel(workers: Workers, task: Workers.Task): Unit =
    level = 0
    while level < blocks.levels do
      workers.run(blocks.levelSize(level), task)
      level += 1

  // `count` items in ranges: a few per worker, or one range for few items.
  private def inRanges(workers: Workers, count: Int, task: Workers.Task): Unit =
    items = count
    ranges = if workers.count == 1 || count < SoftPasses.MinimumShared then 1 else SoftPasses.RangesPerWorker * workers.count
    if rangeResults.length < ranges then rangeResults = new Array[Int](ranges)
    workers.run(ranges, task)

  // Where range `index` of the stage under way starts.
  private def from(index: Int): Int = Workers.rangeStart(items, ranges, index)

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

  /** dp += h v, dAngle += h w, and the turn's cosine and sine: turned by the angle h w itself
    * (its cosine and sine by their series to the 4th and 5th power, then renormalised: no
    * trigonometry per body and substep), so that the arms the substeps turn with them stay
    * where the body's angle puts them after the step. (Turned by the complex number 1 + i h w,
    * as Box2D does, a body turned by atan(h w) per substep, (h w)^3 / 3 less than its angle: at
    * 30 rad/s, a joint's anchor 0.4 m out ended the step 1 mm from where its body put it.)
    */
  private def integratePositions(from: Int, until: Int): Unit =
    val state = workspace.bodies.state
    var i = from
    while i < until do
      val k = i * SoftBodies.Stride
      val vx = state(k + VelocityX); val vy = state(k + VelocityY); val w = state(k + AngularVelocity)
      state(k + ShiftX) += h * vx
      state(k + ShiftY) += h * vy
      if w != 0 then
        val turn = h * w
        state(k + Turn) += turn
        val turn2 = turn * turn
        // The series' coefficients multiply: a division by a constant stays a division.
        val cosTurn = 1 - turn2 * (0.5 - turn2 * SoftPasses.OneOver24)
        val sinTurn = turn * (1 - turn2 * (SoftPasses.Sixth - turn2 * SoftPasses.OneOver120))
        val c = state(k + TurnCos); val s = state(k + TurnSin)
        val turnedC = c * cosTurn - s * sinTurn
        val turnedS = s * cosTurn + c * sinTurn
        // Back to length 1 (the series are not exact). Near it, as after a turn of up to 7 degrees
        // a substep, one Newton step towards 1 / sqrt(n2), 1.5 - n2 / 2, is exact to rounding (its
        // error, 3/8 (n2 - 1)^2, below 4e-17) without a root or a division; a larger turn divides.
        val n2 = turnedC * turnedC + turnedS * turnedS
        if math.abs(n2 - 1) < SoftPasses.NewtonRange then
          val scale = 1.5 - 0.5 * n2
          state(k + TurnCos) = turnedC * scale
          state(k + TurnSin) = turnedS * scale
        else
          val length = math.sqrt(n2)
          state(k + TurnCos) = turnedC / length
          state(k + TurnSin) = turnedS / length
      i += 1

  override def toString: String = s"SoftPasses($blocks)"

private[sims] object SoftPasses:
  /** Fewer bodies or contacts than this are one range: sharing them out costs more than it saves. */
  inline val MinimumShared = 2048
  /** How far from 1 a turned pair's squared length may be for one Newton step to make it 1 to rounding. */
  inline val NewtonRange = 1e-8
  /** The turn's series' coefficients: 1/6, 1/24 and 1/120. */
  private inline val Sixth = 1.0 / 6
  private inline val OneOver24 = 1.0 / 24
  private inline val OneOver120 = 1.0 / 120
  /** Ranges per worker in a shared stage: a worker that starts late finds work left. */
  inline val RangesPerWorker = 4
  /** Items of the contact events' settling judged together (see `settleEvents`): a cache line of verdicts. */
  inline val JudgedBlock = 64
  /** What a range of `finish` found: a body not finite; a body rested long enough to sleep. */
  inline val NotFinite = 1
  inline val ReadyToSleep = 2
