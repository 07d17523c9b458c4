package sims.solver.soft

/** The order in which the soft step's passes take a step's contacts, as blocks that share no
  * moving body, so that the blocks of one level may be solved at once, by several workers,
  * with the same bits as one after the other.
  *
  * The moving bodies are cut into 2^Depth slabs of about equal numbers, from the ground up (or
  * along the longer side of the box around them, without gravity), by their places at the
  * start of the step. A contact whose moving bodies
  * lie in one slab (or that has one moving body) belongs to that slab's block, level 0. The
  * slabs are the leaves of a binary tree; a contact between two slabs belongs to the block of
  * their lowest common node, level 1 for neighbouring pairs of slabs up to level Depth at the
  * root. Two blocks of one level hold bodies of disjoint sets of slabs: they share no moving
  * body. The passes take the levels in turn, 0 first. Worlds with fewer than `MinimumSplit`
  * contacts are one block. Which block a contact joins depends on the bodies' places alone,
  * never on the number of workers.
  *
  * Within a block the contacts keep the collision stage's order, its two halves taken in turn
  * (0, h, 1, h + 1, ...): the collision stage lists a shape's contacts one after another, each
  * waiting in a pass for the one before to update their shared body's velocities, and two
  * contacts from the two halves rarely share a body, so the processor overlaps them.
  */
private[sims] final class ContactBlocks:
  import ContactBlocks.*

  /** The passes' order, place by place: place n's contact, its bodies' offsets in the state
    * and its hot block's offset at `PlaceStride * n` (block k's places are `start(k) until
    * start(k + 1)`), read in order by the passes where the contact's own arrays would be gathered
    * through its index in every pass.
    */
  var places: Array[Int] = new Array[Int](0)
  /** Per place n, its bodies' inverse masses and inertias (mA, iA, mB, iB) at 4 n. */
  var placeMasses: Array[Double] = new Array[Double](0)
  /** Where each block starts among the places (blocks by level: the 2^Depth leaves, then level 1's...). */
  val start: Array[Int] = new Array[Int](BlockCount + 1)
  /** Number of levels this step: 1 (one block) or Depth + 1. */
  var levels: Int = 1

  // Per contact: its block; the contacts sorted by block. Per body: its slab (-1 when it does not
  // move).
  private var blockOf, sorted = new Array[Int](0)
  private var slab = new Array[Int](0)
  private var coordinate = new Array[Double](0)
  private val histogram = new Array[Int](Bins)
  private val bySlab = new Array[Int](Bins)

  /** The first block of `level` (0 to `levels - 1`). */
  def levelStart(level: Int): Int = if levels == 1 then 0 else BlockCount + 1 - (2 << (Depth - level))

  /** The number of blocks of `level`. */
  def levelSize(level: Int): Int = if levels == 1 then 1 else 1 << (Depth - level)

  // The split under way: its contacts, and the ranges of them its stages share out among the
  // workers; per range and block, the range's contacts in the block, then where the next goes
  // (a row of `RowStride` per range: ranges on different cores write different cache lines).
  private var splitting: Contacts = null
  private var splittingBodies: SoftBodies = null
  private var ranges = 1
  private var items = 0
  private var filled = new Array[Int](RowStride)

  private val blocksTask: sims.solver.Workers.Task = r => assignBlocks(from(r), from(r + 1), r * RowStride)
  private val sortTask: sims.solver.Workers.Task = r => sortRange(from(r), from(r + 1), r * RowStride)
  private val interleaveTask: sims.solver.Workers.Task = k => interleave(start(k), start(k + 1), identity = false)

  /** Cuts the first `active` contacts of `contacts` into blocks, between the `bodies`, under
    * gravity `(gx, gy)`; the contacts' blocks and their order found in ranges by the `workers`
    * (the same blocks and order for any number).
    */
  def split(contacts: Contacts, bodies: SoftBodies, gx: Double, gy: Double, workers: sims.solver.Workers): Unit =
    val active = contacts.active
    if blockOf.length < active then
      places = new Array[Int](2 * PlaceStride * active)
      placeMasses = new Array[Double](8 * active)
      blockOf = new Array[Int](2 * active)
      sorted = new Array[Int](2 * active)
    splitting = contacts
    splittingBodies = bodies
    if active < MinimumSplit then
      levels = 1
      start(0) = 0
      start(1) = active
      try interleave(0, active, identity = true)
      finally
        splitting = null
        splittingBodies = null
    else
      levels = Depth + 1
      cutSlabs(bodies, gx, gy)
      items = active
      ranges = if workers.count == 1 then 1 else SoftPasses.RangesPerWorker * workers.count
      if filled.length < ranges * RowStride then filled = new Array[Int](ranges * RowStride)
      try
        workers.run(ranges, blocksTask)
        // Counting sort by block, each block in the collision stage's order: block by block,
        // range by range, where each range's contacts of the block go.
        var placed = 0
        var k = 0
        while k < BlockCount do
          start(k) = placed
          var r = 0
          while r < ranges do
            val n = filled(r * RowStride + k)
            filled(r * RowStride + k) = placed
            placed += n
            r += 1
          k += 1
        start(BlockCount) = placed
        workers.run(ranges, sortTask)
        workers.run(BlockCount, interleaveTask)
      finally
        splitting = null
        splittingBodies = null

  // Where range r of the split under way starts.
  private def from(r: Int): Int = sims.solver.Workers.rangeStart(items, ranges, r)

  /** Gives contacts `from` until `until` of the split their blocks, and counts them by block at
    * `filled(row + block)`.
    */
  private def assignBlocks(from: Int, until: Int, row: Int): Unit =
    val contacts = splitting
    java.util.Arrays.fill(filled, row, row + BlockCount, 0)
    var c = from
    while c < until do
      val a = slab(contacts.bodyA(c))
      val b = slab(contacts.bodyB(c))
      val block =
        if a < 0 then math.max(b, 0)
        else if b < 0 || a == b then a
        else
          // The lowest common node of leaves a and b: `level` bits up, at index a >> level.
          val level = 32 - Integer.numberOfLeadingZeros(a ^ b)
          levelStart(level) + (a >> level)
      blockOf(c) = block
      filled(row + block) += 1
      c += 1

  /** Puts contacts `from` until `until` in `sorted`, each at the next place of its block for
    * this range (`filled(row + block)`).
    */
  private def sortRange(from: Int, until: Int, row: Int): Unit =
    var c = from
    while c < until do
      val k = row + blockOf(c)
      sorted(filled(k)) = c
      filled(k) += 1
      c += 1

  /** Writes places `from until until`: the block's contacts (`sorted(from until until)`, or
    * `from until until` themselves when `identity`), their two halves taken in turn.
    */
  private def interleave(from: Int, until: Int, identity: Boolean): Unit =
    val contacts = splitting
    val bodies = splittingBodies
    val half = (until - from + 1) / 2
    var n = 0
    while n < until - from do
      val i = from + (if (n & 1) == 0 then n >> 1 else half + (n >> 1))
      val c = if identity then i else sorted(i)
      val a = contacts.bodyA(c); val b = contacts.bodyB(c)
      val place = PlaceStride * (from + n)
      places(place) = c
      places(place + 1) = a * SoftBodies.Stride
      places(place + 2) = b * SoftBodies.Stride
      places(place + 3) = contacts.offset(c)
      val m = 4 * (from + n)
      placeMasses(m) = bodies.invMass(a); placeMasses(m + 1) = bodies.invI(a)
      placeMasses(m + 2) = bodies.invMass(b); placeMasses(m + 3) = bodies.invI(b)
      n += 1

  /** Gives every moving body its slab: `Bins` bins along the slabs' axis over the moving bodies'
    * range, each bin's bodies in one slab, the slabs cut where the running count passes each
    * 1 / 2^Depth of the bodies. The axis is the height against gravity `(gx, gy)` (slabs from the
    * ground up: a stack's supports are solved before what they carry, which settled the big
    * pyramids more than slabs side by side, mean drift after 10 s 11.3 against 12.1 cm on
    * large_pyramid, 3.0 against 3.5 cm on pyramid-50), else the longer side of their box.
    */
  private def cutSlabs(bodies: SoftBodies, gx: Double, gy: Double): Unit =
    val n = bodies.count
    if slab.length < n then slab = new Array[Int](2 * n)
    if coordinate.length < n then coordinate = new Array[Double](2 * n)
    val gravity = math.sqrt(gx * gx + gy * gy)
    // The axis (ax, ay): up against gravity, or the longer side of the moving bodies' box.
    val upward = gravity > 0 && !gravity.isInfinite
    var ax = if upward then -gx / gravity else 0.0
    var ay = if upward then -gy / gravity else 0.0
    var i = 0
    if !upward then
      var minX, minY = Double.PositiveInfinity
      var maxX, maxY = Double.NegativeInfinity
      while i < n do
        if bodies.invMass(i) != 0 then
          val x = bodies.startX(i); val y = bodies.startY(i)
          if x < minX then minX = x
          if x > maxX then maxX = x
          if y < minY then minY = y
          if y > maxY then maxY = y
        i += 1
      val wide = maxX - minX >= maxY - minY
      ax = if wide then 1.0 else 0.0
      ay = if wide then 0.0 else 1.0
    var moving = 0
    var low = Double.PositiveInfinity
    var high = Double.NegativeInfinity
    i = 0
    while i < n do
      if bodies.invMass(i) != 0 then
        val value = ax * bodies.startX(i) + ay * bodies.startY(i)
        coordinate(i) = value
        if value < low then low = value
        if value > high then high = value
        moving += 1
      i += 1
    val extent = high - low
    val scale = if extent > 0 && !extent.isInfinite then Bins / extent else 0.0
    java.util.Arrays.fill(histogram, 0)
    i = 0
    while i < n do
      if bodies.invMass(i) != 0 then
        val bin = binOf(coordinate(i), low, scale)
        histogram(bin) += 1
        slab(i) = bin
      else slab(i) = -1
      i += 1
    // Bin to slab: a slab ends where the running count reaches its share.
    var counted = 0
    var current = 0
    var bin = 0
    while bin < Bins do
      bySlab(bin) = current
      counted += histogram(bin)
      while current < Leaves - 1 && counted.toLong * Leaves >= (current + 1).toLong * moving do current += 1
      bin += 1
    i = 0
    while i < n do
      if slab(i) >= 0 then slab(i) = bySlab(slab(i))
      i += 1

  /** The bin of coordinate `value` (bins of width 1 / scale from `low`), within 0 until Bins. */
  private def binOf(value: Double, low: Double, scale: Double): Int =
    val bin = ((value - low) * scale).toInt
    math.max(0, math.min(Bins - 1, bin))

  override def toString: String = s"ContactBlocks(levels = $levels, contacts = ${start(if levels == 1 then 1 else BlockCount)})"

private[sims] object ContactBlocks:
  /** Levels below the root: 2^Depth slabs. */
  inline val Depth = 3
  /** Slabs, the tree's leaves. */
  inline val Leaves = 1 << Depth
  /** Blocks of all levels: 2^(Depth + 1) - 1. */
  inline val BlockCount = 2 * Leaves - 1
  /** Bins of the bodies' histogram along the cut. */
  inline val Bins = 1024
  /** Ints per range's row of counts: the blocks, padded to two cache lines. */
  inline val RowStride = 32
  /** Ints per place (see `places`). */
  inline val PlaceStride = 4
  /** Fewer contacts than this are one block: splitting costs more than sharing saves. */
  inline val MinimumSplit = 4096
