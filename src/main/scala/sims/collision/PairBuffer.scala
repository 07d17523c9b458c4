package sims.collision

import sims.collision.narrowphase.PairSlot
import sims.dynamics.Shape

/** The candidate pairs of one step, handed from the broadphase to the narrowphase: a growable
  * list of pairs of shapes reused from step to step (no tuple per pair), and for the classic
  * step's narrowphase a [[PairSlot]] per place of the list, holding what it keeps for the pair
  * in that place.
  */
private[sims] final class PairBuffer:
  private var slots = new Array[PairSlot](64)
  // The pairs' shapes as indices into `shapes` (the broadphase's array, never changed once made),
  // written by `add`: an Int store, where storing a reference costs the garbage collector's write
  // barrier. The slots get their shapes only in `fillSlots` (the soft step never reads a slot:
  // writing one per pair would cost it a cache miss each).
  private var shapes = Array.empty[Shape]
  private var firsts, seconds = new Array[Int](64)
  private var count = 0
  private var made = 0
  private var filled = true

  /** The most pairs one step may have (see [[sims.Defaults.MaxCandidatePairs]]). */
  var limit: Int = sims.Defaults.MaxCandidatePairs

  /** The setting that raises `limit`, for the error (the classic detector's or the soft step's). */
  var limitName: String = "GridDetector.maxPairs"

  /** Number of pairs. */
  def size: Int = count
  /** Number of slots made so far (slots 0 until `created` exist; those from `size` on are idle). */
  def created: Int = made
  /** The slot of pair i, as the last `fillSlots` left it. */
  def slot(i: Int): PairSlot = slots(i)
  /** The first shape of pair i. */
  def first(i: Int): Shape = shapes(firsts(i))
  /** The second shape of pair i. */
  def second(i: Int): Shape = shapes(seconds(i))
  /** The index of pair i's first shape in the array of the last `clear`. */
  def firstIndex(i: Int): Int = firsts(i)
  /** The index of pair i's second shape in the array of the last `clear`. */
  def secondIndex(i: Int): Int = seconds(i)
  /** Forgets the pairs (the slots stay for reuse). */
  def clear(): Unit =
    count = 0
    filled = false

  /** Forgets the pairs; those added next are shapes of `shapes`, given by their indices there
    * (an array nobody changes while the pairs are read).
    */
  def clear(shapes: Array[Shape]): Unit =
    clear()
    this.shapes = shapes

  /** Whether the slots hold the pairs (`fillSlots` ran since they last changed). */
  def slotsFilled: Boolean = filled

  /** Appends the pair of shapes a and b, indices into the array of the last `clear`; fails once
    * there would be more than `limit` pairs.
    */
  def add(a: Int, b: Int): Unit =
    if count == limit then throw tooMany()
    if count == firsts.length then
      firsts = java.util.Arrays.copyOf(firsts, count * 2)
      seconds = java.util.Arrays.copyOf(seconds, count * 2)
    firsts(count) = a
    seconds(count) = b
    count += 1
    filled = false

  /** Appends the pairs of `other`, whose indices are into the same shapes; fails once there
    * would be more than `limit` pairs.
    */
  def append(other: PairBuffer): Unit =
    if other.count > limit - count then throw tooMany()
    if count + other.count > firsts.length then
      firsts = java.util.Arrays.copyOf(firsts, 2 * (count + other.count))
      seconds = java.util.Arrays.copyOf(seconds, 2 * (count + other.count))
    System.arraycopy(other.firsts, 0, firsts, count, other.count)
    System.arraycopy(other.seconds, 0, seconds, count, other.count)
    count += other.count
    filled = false

  /** Whether passing `limit` throws [[PairBuffer.TooManyPairs]] (a buffer of kept pairs, whose
    * owner catches it) rather than the step's IllegalStateException.
    */
  var keeps: Boolean = false

  private def tooMany(): IllegalStateException =
    val message = s"more than $limit candidate pairs in one step (the limit $limitName): are many shapes " +
      "piled at one place? Raise maxPairs if the scene really has that many overlapping bounds"
    if keeps then PairBuffer.TooManyPairs(message) else IllegalStateException(message)

  /** Gives every pair its slot, made if there is none yet, with the pair's shapes in it. */
  def fillSlots(): Unit =
    if slots.length < count then slots = java.util.Arrays.copyOf(slots, firsts.length)
    var i = 0
    while i < count do
      var s = slots(i)
      if s == null then
        s = PairSlot()
        slots(i) = s
        made += 1
      s.first = shapes(firsts(i))
      s.second = shapes(seconds(i))
      i += 1
    filled = true

private[sims] object PairBuffer:
  /** The failure of a buffer that would hold more than its `limit` of pairs. */
  final class TooManyPairs(message: String) extends IllegalStateException(message)
