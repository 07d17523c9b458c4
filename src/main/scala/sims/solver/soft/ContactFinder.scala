package sims.solver.soft

import sims.collision.{GridDetector, PairBuffer, PairKey}
import sims.collision.broadphase.KeptPairs
import sims.dynamics.World
import sims.solver.Workers

/** The soft step's collision stage, once per step (see docs/two-solvers.md): candidate
  * pairs from bounds enlarged by the speculative distance, then a manifold of at most two
  * points with feature ids per pair, written into the table's new generation with the impulses
  * of the matching points of the last step (warm starting).
  *
  * Persistent contacts: while two bodies have moved little relative to each other since their
  * manifold was computed (see `keeps`), the manifold is kept rather than computed again: its
  * normal stays, its anchors turn with their bodies and its separations follow the bodies'
  * motion, as within the substeps. A stack's contact normals then do not tilt with every tiny
  * rotation of the boxes, which would push them sideways (without this a 12-box stack of 0.5 m
  * boxes leans and falls within 10 s), and the narrowphase is skipped for resting contacts.
  * The idea is Box2D v3.2's "contact recycling" (after PhysX's persistent manifolds). Pairs of
  * circles are computed every step: their normal is the line of their centres whatever their
  * rotation, so keeping it gains no stability, and its anchors, kept while the balls roll
  * past each other, slide apart: the two impulses then form a couple, which changed the
  * angular momentum of 60 balls colliding in free space by 1.5% in 10 s (0.4% without).
  *
  * Pairs of the built-in kinds get their manifold from the narrowphase registry's entry
  * ([[sims.collision.narrowphase.PairFunctions]]); pairs
  * of a user's kinds go through the world's `GridDetector` lists (their `points` and `normal`,
  * the separation being minus the overlap of the shapes' projections on the normal, matched to
  * the last step's points by position). A world whose detector is not a `GridDetector` has all
  * its contacts from its detector's `collisions`, treated as user kinds.
  *
  * Shared out (several workers, many pairs, no body asleep): ranges of pairs are collided at
  * once, each by a [[PairCollider]] of its own into contacts of its own, whose hot and cold
  * blocks go straight into a region of the step's arrays (room for a contact per pair), then
  * gathered into the step's contacts in the ranges' order: the same contacts, in the same order,
  * with the same bits as on one thread. A step with a pair of a user's kinds is collided on one thread (user
  * code need not be safe to run on several at once).
  */
private[sims] final class ContactFinder:
  /** The fewest pairs in a step for which the pairs' shapes and bodies are read ahead in batches
    * (see [[PairCollider.ReadAheadPairs]]; the same contacts either way).
    */
  private[sims] var readAheadPairs: Int = PairCollider.ReadAheadPairs
  // This thread's collider, and one per range of a shared stage with the ranges' contacts.
  private val collider = PairCollider()
  private var colliders = new Array[PairCollider](0)
  private var stages = new Array[Contacts](0)
  private var failures = new Array[Throwable](0)
  private var base = new Array[Int](0)
  private var bodies: SoftBodies = null
  private var world: World = null
  // The shared stage under way: its pairs (or the world's shapes), its ranges, the contacts
  // the ranges' copies go to.
  private var pairs: PairBuffer = null
  private var shapes: Array[sims.dynamics.Shape] = null
  private var ranges = 1
  private var items = 0
  private var current: Contacts = null

  private val refreshTask: Workers.Task = index =>
    sims.dynamics.Shape.refreshCaches(shapes, from(index), from(index + 1))

  private val collideTask: Workers.Task = index =>
    val ranged = colliders(index)
    try
      ranged.collideRange(pairs, from(index), from(index + 1), pairs.size >= readAheadPairs)
    catch case e: Throwable => failures(index) = e

  private val placeTask: Workers.Task = index => current.place(stages(index), base(index))

  // A shared broadphase: its grid, and per range of shapes its pairs and how many it tested.
  private var grid: sims.collision.broadphase.UniformGrid = null
  private var pairRanges = new Array[PairBuffer](0)
  private var pairTests = new Array[Long](0)

  // The workers of the shared search under way, and the search and emission as the kept pairs
  // call them; the kept pairs of an emission under way.
  private var workers: Workers = null
  private val sharedSearch: KeptPairs.Search = new KeptPairs.Search:
    def run(grid: sims.collision.broadphase.UniformGrid, buffer: PairBuffer): Unit = searchShared(grid, buffer)
    override def emit(kept: KeptPairs, grid: sims.collision.broadphase.UniformGrid, pairs: PairBuffer): Unit =
      emitShared(kept, grid, pairs)
  private var kept: KeptPairs = null

  private val pairsTask: Workers.Task = index =>
    pairTests(index) = grid.findPairsOf(from(index), from(index + 1), pairRanges(index))

  private val emitTask: Workers.Task = index =>
    kept.emitRange(grid, from(index), from(index + 1), if index == 0 then pairs else pairRanges(index))

  private val boundsTask: Workers.Task = index => grid.boundsOf(from(index), from(index + 1))

  private val fineCellsTask: Workers.Task = index => grid.fineCellsOf(index, from(index), from(index + 1))

  private val buildTask: Workers.Task = index => grid.buildGridOf(index)

  private val linkTask: Workers.Task = index => grid.linkGridOf(from(index), from(index + 1))

  /** Fills `table.current` with this step's contacts of `world`, whose bodies `bodies` holds,
    * with the world's broadphase in cells of `gridSide` and at most `maxPairs` candidate pairs,
    * the pairs shared out among `workers` when there are many.
    */
  def find(world: World, table: ContactTable, bodies: SoftBodies, workers: Workers, gridSide: Double, maxPairs: Int,
      speculativeDistance: Double, linearSlop: Double, persistence: Double): Unit =
    this.bodies = bodies
    this.world = world
    table.begin()
    collider.begin(world, table, bodies, table.current, speculativeDistance, linearSlop, persistence, shared = false)
    if bodies.anyAsleep then wakeOnMovedFixed(table.committed)
    world.detector match
      case detector: GridDetector =>
        val stages = world.collisionPipeline
        if workers.count > 1 && world.shapeBuffer.length >= SoftPasses.MinimumShared then
          findPairsShared(workers, world, gridSide, maxPairs, speculativeDistance)
        else
          stages.findKeptPairs(world.shapeBuffer, gridSide, maxPairs, "SoftStep.maxPairs", speculativeDistance,
            world.timeStep, world.revision)
        val pairs = stages.pairs
        val narrowphase = stages.narrowphase
        narrowphase.update(detector.detectionMethods, detector.collisionMethods)
        if !bodies.anyAsleep then
          val shared = workers.count > 1 && pairs.size >= SoftPasses.MinimumShared &&
            collideShared(workers, table, pairs, speculativeDistance, linearSlop, persistence)
          if !shared then collider.collideRange(pairs, 0, pairs.size, pairs.size >= readAheadPairs)
        else
          // Sleeping islands touched by an awake body (or by a fixed body the user moved) wake
          // first, and the islands they touch in turn; then the pairs with a moving body are
          // collided, and the contacts of pairs still asleep are carried over unchanged, after
          // them (the passes solve only the first `active`).
          var woke = true
          while woke do
            woke = false
            var i = 0
            while i < pairs.size do
              val a = pairs.first(i)
              val b = pairs.second(i)
              val ia = a.body.index
              val ib = b.body.index
              val sleeper = if bodies.asleep(ia) && wakes(ib) then ia else if bodies.asleep(ib) && wakes(ia) then ib else -1
              if sleeper >= 0 && collider.touches(a, b) then
                bodies.wakeIsland(bodies.bodies(sleeper).sleepIsland)
                woke = true
              i += 1
          var i = 0
          while i < pairs.size do
            val a = pairs.first(i)
            val b = pairs.second(i)
            if bodies.invMass(a.body.index) != 0 || bodies.invMass(b.body.index) != 0 then
              collider.collide(a, b)
            i += 1
          table.current.active = table.current.count
          i = 0
          while i < pairs.size do
            val a = pairs.first(i)
            val b = pairs.second(i)
            if bodies.invMass(a.body.index) == 0 && bodies.invMass(b.body.index) == 0 then
              val key = PairKey.of(a, b)
              val last = collider.lastOf(key)
              if last >= 0 then collider.carry(last, a, b, key)
              // A pair asleep with no contact kept (the last step did not look for contacts, or
              // the user put the bodies to sleep): its manifold now, to warm-start from 0.
              else collider.collide(a, b)
            i += 1
      case detector =>
        detector.detect()
        val collisions = detector.collisions
        table.current.pairsRepeat = true
        // A detector of the user's finds every colliding pair: a sleeper colliding with a body
        // that wakes it wakes, and the islands it touches in turn.
        var woke = bodies.anyAsleep
        while woke do
          woke = false
          var i = 0
          while i < collisions.length do
            val ia = collisions(i).shape1.body.index
            val ib = collisions(i).shape2.body.index
            val sleeper = if bodies.asleep(ia) && wakes(ib) then ia else if bodies.asleep(ib) && wakes(ia) then ib else -1
            if sleeper >= 0 then
              bodies.wakeIsland(bodies.bodies(sleeper).sleepIsland)
              woke = true
            i += 1
        var i = 0
        while i < collisions.length do
          val c = collisions(i)
          val key = PairKey.of(c.shape1, c.shape2)
          collider.addCollision(c, key, collider.lastOf(key))
          i += 1
    if !bodies.anyAsleep || !world.detector.isInstanceOf[GridDetector] then table.current.active = table.current.count

  /** The broadphase's pairs, its bounds and any search for kept pairs in ranges of shapes shared
    * out among `workers` (see [[sims.collision.broadphase.UniformGrid.beginSharedGrid]]): the same
    * pairs, in the same order, as on one thread.
    */
  private def findPairsShared(workers: Workers, world: World, gridSide: Double, maxPairs: Int,
      speculativeDistance: Double): Unit =
    val stages = world.collisionPipeline
    val shapes = world.shapeBuffer
    stages.beginSharedBounds(shapes, gridSide, maxPairs, "SoftStep.maxPairs", speculativeDistance, world.timeStep)
    val count = ContactFinder.RangesPerWorker * workers.count
    grid = stages.broadphase
    ranges = count
    items = shapes.length
    try workers.run(count, boundsTask)
    finally grid = null
    this.workers = workers
    try stages.kept.pairsOf(stages.broadphase, world.revision, maxPairs, "SoftStep.maxPairs", stages.pairs, sharedSearch)
    finally this.workers = null

  /** The grid's full search for the kept pairs (see [[KeptPairs.update]]), into `buffer`,
    * shared out among `workers`.
    */
  private def searchShared(grid: sims.collision.broadphase.UniformGrid, buffer: PairBuffer): Unit =
    val workers = this.workers
    this.grid = grid
    try
      // The fine cells and the fine grid in a range of shapes per worker (each shape's share of
      // the work is about the same), the grid's chains then joined in ranges of cells.
      ranges = math.min(workers.count, ContactFinder.MostGridRanges)
      grid.beginFineCells(ranges)
      workers.run(ranges, fineCellsTask)
      grid.endFineCells()
      if grid.beginSharedGrid(buffer) then
        workers.run(ranges, buildTask)
        items = grid.gridCells
        workers.run(ranges, linkTask)
        grid.endSharedGrid()
    finally this.grid = null
    val count = ContactFinder.RangesPerWorker * workers.count
    rangeBuffers(count, buffer)
    this.grid = grid
    ranges = count
    items = grid.shapeCount
    try workers.run(count, pairsTask)
    finally this.grid = null
    var tests = 0L
    var r = 0
    while r < count do
      tests += pairTests(r)
      r += 1
    grid.endShared(buffer, pairRanges, count, tests)

  /** The kept pairs' emission (see [[KeptPairs.emitRange]]) into `pairs`, in ranges shared out
    * among `workers`: the first range's into `pairs`, each other's into a buffer of its own with
    * the limit of `pairs`, appended in order: the same pairs, in the same order, as on one thread.
    */
  private def emitShared(kept: KeptPairs, grid: sims.collision.broadphase.UniformGrid, pairs: PairBuffer): Unit =
    if kept.keptCount < SoftPasses.MinimumShared then kept.emit(grid, pairs)
    else
      val count = ContactFinder.RangesPerWorker * workers.count
      rangeBuffers(count, pairs)
      this.kept = kept
      this.grid = grid
      this.pairs = pairs
      ranges = count
      items = kept.keptCount
      try workers.run(count, emitTask)
      finally
        this.grid = null
        this.kept = null
        this.pairs = null
      var r = 1
      while r < count do
        pairs.append(pairRanges(r))
        r += 1
      kept.endEmit(grid)

  /** Makes `count` buffers of pairs for ranges of a shared stage, with the limit, its name and the
    * failure of `like`.
    */
  private def rangeBuffers(count: Int, like: PairBuffer): Unit =
    if pairRanges.length < count then
      pairRanges = Array.fill(count)(PairBuffer())
      pairTests = new Array[Long](count)
    var r = 0
    while r < count do
      pairRanges(r).limit = like.limit
      pairRanges(r).keeps = like.keeps
      pairRanges(r).limitName = like.limitName
      r += 1

  /** Collides `pairs` in ranges shared out among `workers`, into `table.current` in the ranges'
    * order; false, with nothing added, when a range met a pair of a user's kinds. A failure (a
    * speed too large to compute with) is the first range's that failed: the first pair's, as
    * on one thread.
    */
  private def collideShared(workers: Workers, table: ContactTable, pairs: PairBuffer, speculativeDistance: Double,
      linearSlop: Double, persistence: Double): Boolean =
    val count = ContactFinder.RangesPerWorker * workers.count
    if colliders.length < count then
      colliders = Array.fill(count)(PairCollider())
      stages = Array.fill(count)(Contacts())
      failures = new Array[Throwable](count)
      base = new Array[Int](count)
    this.pairs = pairs
    ranges = count
    // The shapes' cached geometry (a polygon's side normals) computed before the ranges read it.
    shapes = world.shapeBuffer
    items = shapes.length
    workers.run(count, refreshTask)
    shapes = null
    items = pairs.size
    // Each range's blocks in a region of the step's arrays with room for a contact of two points
    // per pair (a pair makes one contact at most): gathering the ranges then copies no block.
    val target = table.current
    target.reserve(items)
    var r = 0
    while r < count do
      stages(r).share(target, from(r), from(r + 1))
      colliders(r).begin(world, table, bodies, stages(r), speculativeDistance, linearSlop, persistence, shared = true)
      failures(r) = null
      r += 1
    workers.run(count, collideTask)
    this.pairs = null
    r = 0
    while r < count && !colliders(r).metGeneral do r += 1
    if r < count then false
    else
      r = 0
      while r < count do
        if failures(r) != null then
          val failure = failures(r)
          java.util.Arrays.fill(failures.asInstanceOf[Array[AnyRef]], null)
          throw failure
        r += 1
      current = table.current
      var more = 0
      r = 0
      while r < count do
        base(r) = current.count + more
        more += stages(r).count
        if stages(r).bouncing then current.bouncing = true
        r += 1
      current.extend(more, items)
      workers.run(count, placeTask)
      current = null
      true

  // Where range `index` of the shared stage under way starts.
  private def from(index: Int): Int = Workers.rangeStart(items, ranges, index)

  /** Wakes the sleeping islands that touched, at the last step, a fixed body the user placed
    * since: it may have moved away from them (they would hang in the air) or into them.
    */
  private def wakeOnMovedFixed(committed: Contacts): Unit =
    var c = 0
    while c < committed.count do
      val a = committed.shapeA(c).body.index
      val b = committed.shapeB(c).body.index
      if a >= 0 && b >= 0 then
        if bodies.asleep(a) && !bodies.asleep(b) && bodies.bodies(b).movedByUser then
          bodies.wakeIsland(bodies.bodies(a).sleepIsland)
        else if bodies.asleep(b) && !bodies.asleep(a) && bodies.bodies(a).movedByUser then
          bodies.wakeIsland(bodies.bodies(b).sleepIsland)
      c += 1

  /** Whether body i wakes a sleeping body it touches: it moves (awake and not fixed, or
    * kinematic with a velocity), or it is a fixed body the user placed since the last step.
    */
  private def wakes(i: Int): Boolean =
    if bodies.invMass(i) != 0 then true
    else
      val body = bodies.bodies(i)
      body.movesItself || (!bodies.asleep(i) && body.movedByUser)

  override def toString: String = s"ContactFinder(ranges = ${colliders.length})"

private object ContactFinder:
  /** Ranges of pairs per worker in a shared stage: a worker that starts late finds work left. */
  inline val RangesPerWorker = 4

  /** Ranges of shapes that fill the fine grid at most: each keeps a chain per cell of the grid
    * (three Ints a cell), and each cell's chains are joined one by one.
    */
  inline val MostGridRanges = 8
