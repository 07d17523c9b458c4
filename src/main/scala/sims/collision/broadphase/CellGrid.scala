package sims.collision.broadphase

/** The broadphase's grid: from cell (cx, cy) to a chain of entries (shape indices), rebuilt
  * every step without allocating once it has grown. Sparse, an open-addressing hash table of
  * the cells in use; or dense, when the cells in use lie in a box of `columns` x `rows` from
  * (0, 0) with not many more cells than shapes (a pile, a pit): slot cx rows + cy, no hashing.
  * Lookups depend only on the cell coordinates, never on object identity, so pair order is
  * deterministic, and the same in both forms.
  */
private[broadphase] final class CellGrid:
  private var keys = new Array[Long](1024)
  private var stamps = new Array[Int](1024) // slot in use when stamps(slot) == stamp
  private var heads = new Array[Int](1024)
  private var mask = 1023
  private var stamp = 1
  private var used = 0
  private var entryShape = new Array[Int](1024)
  private var entryNext = new Array[Int](1024)
  private var entries = 0
  private var dense = false
  private var columns, rows = 0
  // A dense grid built by ranges of shapes at once (see `beginRanges`): per range and cell, the
  // range's own chain, its first and last entry, valid where the range's stamp is `stamp`.
  private var ranges = 0
  private var rangeHeads, rangeTails, rangeStamps = new Array[Int](0)

  /** Empties the grid, sized for about `shapes` shapes whose cells will lie in the box of
    * `columns` x `rows` cells from (0, 0), if that is known (0 x 0 if not).
    */
  def reset(shapes: Int, columns: Int = 0, rows: Int = 0): Unit =
    val cells = columns.toDouble * rows
    dense = columns > 0 && rows > 0 && cells <= CellGrid.DenseCellsPerShape * shapes + CellGrid.DenseCellsAlways
    this.columns = columns
    this.rows = rows
    val needed = if dense then cells.toInt else 4 * shapes
    if keys.length < needed then resize(Integer.highestOneBit(math.max(needed, 1024)) * 2)
    stamp += 1
    if stamp == Int.MaxValue then
      java.util.Arrays.fill(stamps, 0)
      java.util.Arrays.fill(rangeStamps, 0)
      stamp = 1
    used = 0
    entries = 0

  /** Whether the grid is dense since the last `reset`. */
  def isDense: Boolean = dense

  /** The cells of a dense grid, `columns` x `rows`. */
  def cells: Int = columns * rows

  /** Starts filling an empty dense grid from `ranges` ranges of shapes at once, with `entries`
    * entries in all: each range puts its shapes into chains of its own (`insertInRange`), then
    * `linkRanges` joins each cell's chains, the last range's first: the chains `insert` makes
    * when the ranges' shapes come in order.
    */
  def beginRanges(ranges: Int, entries: Int): Unit =
    if !dense then throw IllegalStateException("the ranges fill a dense grid only")
    this.ranges = ranges
    if entryShape.length < entries then
      entryShape = new Array[Int](2 * entries)
      entryNext = new Array[Int](2 * entries)
    this.entries = entries
    val slots = ranges * cells
    if rangeStamps.length < slots then
      rangeHeads = new Array[Int](2 * slots)
      rangeTails = new Array[Int](2 * slots)
      rangeStamps = new Array[Int](2 * slots) // 0: no stamp, which starts at 1

  /** Adds shape index `shape` as entry `entry` to the front of range `range`'s chain of cell
    * (cx, cy): writes that entry and the range's slots only.
    */
  def insertInRange(range: Int, cx: Int, cy: Int, shape: Int, entry: Int): Unit =
    val k = range * cells + cx * rows + cy
    entryShape(entry) = shape
    if rangeStamps(k) != stamp then
      rangeStamps(k) = stamp
      rangeTails(k) = entry
      entryNext(entry) = -1
    else entryNext(entry) = rangeHeads(k)
    rangeHeads(k) = entry

  /** Joins the ranges' chains of the cells (slots) `from` until `until`, the last range's first. */
  def linkRanges(from: Int, until: Int): Unit =
    val cells = this.cells
    var slot = from
    while slot < until do
      var head = -1
      var tail = -1
      var r = ranges - 1
      while r >= 0 do
        val k = r * cells + slot
        if rangeStamps(k) == stamp then
          if tail >= 0 then entryNext(tail) = rangeHeads(k) else head = rangeHeads(k)
          tail = rangeTails(k)
        r -= 1
      if head >= 0 then
        stamps(slot) = stamp
        heads(slot) = head
      slot += 1

  /** The slot of cell (cx, cy), claimed for it (with an empty chain) if the cell was empty:
    * for `head` and `push`, until the next `open` or `reset`. One probe serves a cell's visit
    * and the insertion after it.
    */
  def open(cx: Int, cy: Int): Int =
    if dense then
      val slot = cx * rows + cy
      if stamps(slot) != stamp then
        stamps(slot) = stamp
        heads(slot) = -1
      slot
    else
      if 2 * (used + 1) > keys.length then rehash()
      val key = CellGrid.key(cx, cy)
      val slot = find(key)
      if stamps(slot) != stamp then
        stamps(slot) = stamp
        keys(slot) = key
        heads(slot) = -1
        used += 1
      slot

  /** First entry of the chain of an `open` slot, or -1 for an empty cell. */
  def head(slot: Int): Int = heads(slot)

  /** Next entry in the same chain, or -1. */
  def nextEntry(entry: Int): Int = entryNext(entry)

  /** The shape index stored in an entry. */
  def shapeOf(entry: Int): Int = entryShape(entry)

  /** Adds shape index `shape` to the front of the chain of an `open` slot. */
  def push(slot: Int, shape: Int): Unit =
    if entries == entryShape.length then
      entryShape = java.util.Arrays.copyOf(entryShape, entries * 2)
      entryNext = java.util.Arrays.copyOf(entryNext, entries * 2)
    entryShape(entries) = shape
    entryNext(entries) = heads(slot)
    heads(slot) = entries
    entries += 1

  /** First entry of the cell's chain, or -1 for an empty cell (the cell is not claimed). */
  def firstEntry(cx: Int, cy: Int): Int =
    val slot =
      if !dense then find(CellGrid.key(cx, cy))
      else if cx >= 0 && cx < columns && cy >= 0 && cy < rows then cx * rows + cy
      else -1
    if slot >= 0 && stamps(slot) == stamp then heads(slot) else -1

  /** Adds shape index `shape` to cell (cx, cy). */
  def insert(cx: Int, cy: Int, shape: Int): Unit = push(open(cx, cy), shape)

  /** Slot of `key`, or the empty slot where it would go (linear probing). */
  private def find(key: Long): Int =
    var slot = CellGrid.hash(key) & mask
    while stamps(slot) == stamp && keys(slot) != key do slot = (slot + 1) & mask
    slot

  private def resize(capacity: Int): Unit =
    keys = new Array[Long](capacity)
    stamps = new Array[Int](capacity)
    heads = new Array[Int](capacity)
    mask = capacity - 1
    // The stamps start again: no range's slot may hold one of the new stamps.
    java.util.Arrays.fill(rangeStamps, 0)
    stamp = 1
    used = 0

  /** Doubles the table, keeping the cells of the current stamp. */
  private def rehash(): Unit =
    val (oldKeys, oldStamps, oldHeads, oldStamp) = (keys, stamps, heads, stamp)
    resize(keys.length * 2)
    var i = 0
    while i < oldKeys.length do
      if oldStamps(i) == oldStamp then
        val slot = find(oldKeys(i))
        stamps(slot) = stamp
        keys(slot) = oldKeys(i)
        heads(slot) = oldHeads(i)
        used += 1
      i += 1

private object CellGrid:
  /** A grid is dense when its box has at most this many cells per shape, plus `DenseCellsAlways`. */
  val DenseCellsPerShape = 4.0
  val DenseCellsAlways = 4096.0

  inline def key(cx: Int, cy: Int): Long = (cx.toLong << 32) | (cy.toLong & 0xffffffffL)
  inline def hash(key: Long): Int =
    val h = key * 0x9e3779b97f4a7c15L
    (h ^ (h >>> 29)).toInt
