package sims.collision.broadphase

/** The broadphase's sparse grid: an open-addressing hash table from cell (cx, cy) to a chain of
  * entries (shape indices), rebuilt every step without allocating once it has grown. Lookups
  * depend only on the cell coordinates, never on object identity, so pair order is
  * deterministic.
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

  /** Empties the grid, sized for about `shapes` shapes. */
  def reset(shapes: Int): Unit =
    if keys.length < 4 * shapes then resize(Integer.highestOneBit(math.max(4 * shapes, 1024)) * 2)
    stamp += 1
    if stamp == Int.MaxValue then
      java.util.Arrays.fill(stamps, 0)
      stamp = 1
    used = 0
    entries = 0

  /** The slot of cell (cx, cy), claimed for it (with an empty chain) if the cell was empty:
    * for `head` and `push`, until the next `open` or `reset`. One probe serves a cell's visit
    * and the insertion after it.
    */
  def open(cx: Int, cy: Int): Int =
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
    val slot = find(CellGrid.key(cx, cy))
    if stamps(slot) == stamp then heads(slot) else -1

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
  inline def key(cx: Int, cy: Int): Long = (cx.toLong << 32) | (cy.toLong & 0xffffffffL)
  inline def hash(key: Long): Int =
    val h = key * 0x9e3779b97f4a7c15L
    (h ^ (h >>> 29)).toInt
