package sims.collision

import sims.dynamics.Shape

/** One candidate pair of the broadphase, with what the narrowphase needs to rerun on it
  * cheaply: the resolved methods, one reusable collision object per built-in kind, and the
  * last result together with the bodies' move counts it was computed at. Slots are reused
  * from step to step, so a steady scene allocates nothing here.
  */
private[collision] final class PairSlot:
  var first: Shape = null
  var second: Shape = null
  /** The methods for the pair's shape classes (resolved once per step). */
  var methods: NarrowphaseCache.Resolved = null
  var circle: CircleCollision = null
  var polyCircle: PolyCircleCollision = null
  var poly: PolyCollision = null
  // The last narrowphase result of this slot and the inputs it was computed from.
  var doneFirst: Shape = null
  var doneSecond: Shape = null
  var doneMoves1: Long = -1
  var doneMoves2: Long = -1
  var result: Collision = null
  // For two centred circles found apart: their gap (less a rounding margin) and the bodies'
  // travel and jump counts then. While the bodies have travelled less than the gap in total,
  // the circles are still apart: the test would say so again.
  var gap: Double = 0
  var doneTravel1: Double = 0
  var doneTravel2: Double = 0
  var doneJumps1: Long = -1
  var doneJumps2: Long = -1

  /** Forgets the last result (its inputs can no longer be trusted). */
  def invalidate(): Unit =
    doneFirst = null
    doneSecond = null
    result = null

/** A growable list of pair slots, reused from step to step (no tuple per pair). */
private[collision] final class PairBuffer:
  private var slots = new Array[PairSlot](64)
  private var count = 0

  private var made = 0

  def size: Int = count
  /** Number of slots made so far (slots 0 until `created` exist; those from `size` on are idle). */
  def created: Int = made
  def slot(i: Int): PairSlot = slots(i)
  def first(i: Int): Shape = slots(i).first
  def second(i: Int): Shape = slots(i).second
  def clear(): Unit = count = 0

  def add(a: Shape, b: Shape): Unit =
    if count == slots.length then slots = java.util.Arrays.copyOf(slots, count * 2)
    var s = slots(count)
    if s == null then
      s = PairSlot()
      slots(count) = s
      made += 1
    s.first = a
    s.second = b
    count += 1
