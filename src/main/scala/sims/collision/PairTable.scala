package sims.collision

import sims.dynamics.Shape

/** A table of pairs of shapes: a hash table by open addressing from a pair's key ([[PairKey]])
  * to its two shapes and a stamp (the open pairs of a [[PairTracker]]). A key and its stamp share a cache line, so
  * touching a pair costs one probe; pairs leave by tombstone, so a scan over the slots may
  * remove what it visits. Slot order depends on the keys and on the order of changes only: what
  * the tracker reports from a scan it sorts by key, so nothing depends on it.
  */
private[sims] final class PairTable:
  import PairTable.*

  // Slot s: cells(2 s) = its key (or Empty, Removed), cells(2 s + 1) = its stamp.
  private var cells = emptyCells(64)
  private var firsts = new Array[Shape](64)
  private var seconds = new Array[Shape](64)
  // The arrays of the last rehash at this size, for the next: clearing out removed slots, as a
  // table whose pairs come and go must do every few steps, allocates nothing.
  private var spareCells = Array.emptyLongArray
  private var spareFirsts, spareSeconds = Array.empty[Shape]
  private var mask = 63
  private var live = 0
  private var removed = 0
  // The slots filled since the last clear or rehash, so that `clear` empties those alone (a table
  // rebuilt every step has most of its slots empty). At most half the slots are in use, so the
  // log overflows only where removed slots are filled again; `filled` then exceeds its length and
  // `clear` empties every slot.
  private var filledSlots = new Array[Int](32)
  private var filled = 0
  private var rehashCount = 0

  /** Number of pairs. */
  def size: Int = live

  /** Number of slots (scan them with `keyAt`). */
  def slots: Int = mask + 1

  /** The key in `slot`, or a negative value for an empty slot. */
  def keyAt(slot: Int): Long = cells(2 * slot)

  /** The stamp of the pair in `slot`. */
  def stampAt(slot: Int): Long = cells(2 * slot + 1)

  /** Sets the stamp of the pair in `slot`. */
  def stamp(slot: Int, value: Long): Unit = cells(2 * slot + 1) = value

  /** The first shape of the pair in `slot`. */
  def firstAt(slot: Int): Shape = firsts(slot)

  /** The second shape of the pair in `slot`. */
  def secondAt(slot: Int): Shape = seconds(slot)

  /** The slot of `key`, or -1. */
  def find(key: Long): Int =
    var slot = hash(key) & mask
    var k = cells(2 * slot)
    while k != Empty && k != key do
      slot = (slot + 1) & mask
      k = cells(2 * slot)
    if k == key then slot else -1

  /** Adds the pair `key` (not in the table) with its shapes and stamp; returns its slot. */
  def insert(key: Long, first: Shape, second: Shape, stampValue: Long): Int =
    if 2 * (live + removed + 1) > slots then rehash(if 4 * (live + 1) > slots then 2 * slots else slots)
    place(key, first, second, stampValue)

  /** Counts the rehashes, each of which moves every pair to another slot. */
  def rehashes: Int = rehashCount

  private def place(key: Long, first: Shape, second: Shape, stampValue: Long): Int =
    var slot = hash(key) & mask
    while cells(2 * slot) >= 0 do slot = (slot + 1) & mask // past live slots to an empty or removed one
    if cells(2 * slot) == Removed then removed -= 1
    fill(slot, key, stampValue)
    firsts(slot) = first
    seconds(slot) = second
    slot

  private def fill(slot: Int, key: Long, stampValue: Long): Unit =
    cells(2 * slot) = key
    cells(2 * slot + 1) = stampValue
    if filled < filledSlots.length then filledSlots(filled) = slot
    filled += 1
    live += 1

  /** Takes the pair in `slot` out. */
  def remove(slot: Int): Unit =
    cells(2 * slot) = Removed
    firsts(slot) = null
    seconds(slot) = null
    live -= 1
    removed += 1

  /** Takes every pair out. */
  def clear(): Unit =
    if filled <= filledSlots.length then
      var i = 0
      while i < filled do
        val slot = filledSlots(i)
        cells(2 * slot) = Empty
        firsts(slot) = null
        seconds(slot) = null
        i += 1
    else
      java.util.Arrays.fill(cells, Empty)
      java.util.Arrays.fill(firsts.asInstanceOf[Array[AnyRef]], null)
      java.util.Arrays.fill(seconds.asInstanceOf[Array[AnyRef]], null)
    filled = 0
    live = 0
    removed = 0

  /** Moves the pairs into arrays of `capacity` slots (the spare ones if they have that size),
    * leaving out the removed slots.
    */
  private def rehash(capacity: Int): Unit =
    val (oldCells, oldFirsts, oldSeconds) = (cells, firsts, seconds)
    rehashCount += 1
    if spareCells.length == 2 * capacity then
      cells = spareCells; firsts = spareFirsts; seconds = spareSeconds
      java.util.Arrays.fill(cells, Empty)
    else
      cells = emptyCells(capacity)
      firsts = new Array[Shape](capacity)
      seconds = new Array[Shape](capacity)
    mask = capacity - 1
    if filledSlots.length != capacity / 2 then filledSlots = new Array[Int](capacity / 2)
    filled = 0
    live = 0
    removed = 0
    var slot = 0
    while 2 * slot < oldCells.length do
      if oldCells(2 * slot) >= 0 then
        place(oldCells(2 * slot), oldFirsts(slot), oldSeconds(slot), oldCells(2 * slot + 1))
      slot += 1
    java.util.Arrays.fill(oldFirsts.asInstanceOf[Array[AnyRef]], null)
    java.util.Arrays.fill(oldSeconds.asInstanceOf[Array[AnyRef]], null)
    spareCells = oldCells; spareFirsts = oldFirsts; spareSeconds = oldSeconds

private object PairTable:
  /** The key of an empty slot (keys are at least 0). */
  inline val Empty = -1L
  /** The key of a slot whose pair was taken out. */
  inline val Removed = -2L

  private def emptyCells(capacity: Int): Array[Long] =
    val cells = new Array[Long](2 * capacity)
    java.util.Arrays.fill(cells, Empty)
    cells

  private inline def hash(key: Long): Int =
    val h = key * 0x9e3779b97f4a7c15L
    (h ^ (h >>> 29)).toInt
