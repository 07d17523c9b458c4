package sims.collision

import sims.Defaults
import sims.dynamics.{Shape, World}

/** Which pairs of shapes touch (or, for sensors, overlap) from step to step, and the begins and
  * ends of each step: the bookkeeping behind [[ContactEvents]] and [[SensorEvents]].
  *
  * A pair is identified by its two shapes' `worldIndex`es (the order they joined the world:
  * never reused, unchanged when other bodies leave), packed into a Long key. For contacts the
  * earlier shape comes first; for sensors (`ordered`) the sensor comes first. The pairs that
  * have begun and not ended are the open pairs, kept in a [[PairTable]]. During a step the solver
  * (or the sensor stage) calls `touch` for every pair touching now: an open pair is marked, a new
  * one opened at once and recorded as a begin. `finishStep` then ends every open pair not marked
  * this step, unless it may stay open (contacts only, see `keeps`). Every
  * begin is thus followed by exactly one end: a pair that stops touching, whose shape leaves the
  * world, stops colliding (`collidable`, filter bits, a sensor flag, a joint's
  * `collideConnected`) or whose world stops detecting collisions ends at the next step, whichever
  * solver runs it.
  *
  * The pairs touch in much the same order every step (a solver lists its contacts in its
  * broadphase's order), so the tracker also keeps the open pairs as a list, in the order of the
  * last step's touches (then the pairs kept open untouched), each with its slot in the table. A
  * touch first looks for its pair near the last one found in that list, a little ahead and then a
  * little behind (`PairKey.near`): a few comparisons of keys in a row, where a probe of the table
  * is a cache miss in a big scene. Only a pair not found there probes the table. The pairs
  * touched are marked in a bit per slot, and
  * `finishStep` visits the list to find the open pairs not touched, instead of scanning every
  * slot. After an undo, a restore or a rehash of the table the list may not be the open pairs:
  * that step probes for every touch and scans the table, and leaves a list for the next.
  *
  * The begins and ends of a step are kept as plain arrays, sorted by key (the shapes' world order,
  * never a hash order) and turned into event objects only when someone reads them. The last
  * step's are kept beside the ones being made, so that a failed step can be undone: its begins
  * leave the table, its ends return.
  *
  * @param ordered whether the pair's order is given (sensor first), rather than by world order
  */
private[sims] final class PairTracker(ordered: Boolean):
  import PairTracker.*

  private val open = PairTable()
  // Per slot of `open`, whether its pair was touched this step.
  private var touched = new Array[Long](1)
  // The open pairs after the last step (`listed` of them), in the order of its touches and then
  // those kept untouched: keys and slots. Exactly the open pairs when `listKnown`.
  private var listKeys = new Array[Long](64)
  private var listSlots = new Array[Int](64)
  private var listed = 0
  private var listKnown = false
  // Where the next touch is looked for in the list: after the last pair found there.
  private var cursor = 0
  // This step's touches in order (each pair once), and then the pairs `finishStep` keeps open
  // untouched: the next step's list.
  private var touchKeys = new Array[Long](64)
  private var touchSlots = new Array[Int](64)
  private var touchCount = 0
  private var rehashesSeen = 0
  // The events of the step under way, and those of the last finished step (shown).
  private var working = StepEvents()
  private var shown = StepEvents()
  // Whether this step's `finishStep` made `working` the shown events.
  private var finished = false
  private var lastFlipped = false
  // Set by `touchAllOpen`: this step keeps every open pair, and reports no other.
  private var allOpenTouched = false
  private val separation = ShapeSeparation()
  // The finish under way (see `beginFinish`): its items (of the list, or the table's slots), and
  // per item its verdict.
  private var judging = 0
  private var judgingList = false
  private var verdicts = new Array[Byte](64)

  /** Counts the touches that probed the table, not finding their pair in the list. */
  private[collision] var probes: Long = 0

  /** Counts the changes of the shown events (steps finished, undone, restored). */
  var generation: Long = 0

  /** Starts a step: no pair touched yet, no begins, no ends. */
  def beginStep(): Unit =
    val words = (open.slots + 63) >> 6
    if touched.length != words then touched = new Array[Long](words)
    else java.util.Arrays.fill(touched, 0L)
    if open.rehashes != rehashesSeen then listKnown = false // an undo or a restore grew the table
    rehashesSeen = open.rehashes
    cursor = 0
    touchCount = 0
    allOpenTouched = false
    working.clear()
    finished = false

  /** Reports that shapes `a` and `b` touch now; true if that begins their pair (it was not open
    * and not reported yet this step): the caller then describes it with `describe`.
    */
  def touch(a: Shape, b: Shape): Boolean =
    // A contact pair of a shape whose contact events are off is not tracked (sensor pairs are).
    if !ordered && (!a.enableContactEvents || !b.enableContactEvents) then false
    else touchKey(PairKey.of(a, b), a, b)

  /** `touch` for shapes `a` and `b` whose pair's key in that order is `pairKey`, and whose contact
    * events are on (the caller knows it): the shapes are read only if the pair begins (a solver
    * that keeps its contacts' keys spares a cache miss a touch).
    */
  def touchKey(pairKey: Long, a: Shape, b: Shape): Boolean =
    // The key's halves are a's and b's world indices (see PairKey.of): b's first if it is earlier.
    lastFlipped = !ordered && pairKey.toInt < (pairKey >>> 32).toInt
    val key = if lastFlipped then (pairKey << 32) | (pairKey >>> 32) else pairKey
    if listKnown then
      val p = PairKey.near(listKeys, listed, cursor, key)
      if p >= 0 then
        if p >= cursor then cursor = p + 1 // found ahead: the touches go on from there
        mark(key, listSlots(p))
        return false
    probes += 1
    val slot = open.find(key)
    if slot >= 0 then
      mark(key, slot)
      false
    else
      val first = if lastFlipped then b else a
      val second = if lastFlipped then a else b
      val placed = open.insert(key, first, second, 0)
      if open.rehashes == rehashesSeen then mark(key, placed)
      else
        addTouch(key, placed)
        remark()
      working.addBegin(key, first, second)
      true

  /** Marks the pair `key` in `slot` touched, and adds it to this step's touches if it was not
    * yet (a pair a solver lists twice is touched twice).
    */
  private def mark(key: Long, slot: Int): Unit =
    if !isTouched(slot) then
      setTouched(slot)
      addTouch(key, slot)

  private inline def isTouched(slot: Int): Boolean = (touched(slot >> 6) & (1L << (slot & 63))) != 0

  private inline def setTouched(slot: Int): Unit = touched(slot >> 6) |= 1L << (slot & 63)

  private def addTouch(key: Long, slot: Int): Unit =
    if touchCount == touchKeys.length then
      touchKeys = java.util.Arrays.copyOf(touchKeys, 2 * touchCount)
      touchSlots = java.util.Arrays.copyOf(touchSlots, 2 * touchCount)
    touchKeys(touchCount) = key
    touchSlots(touchCount) = slot
    touchCount += 1

  /** After the table rehashed to insert a pair: every pair has a new slot. Marks this step's
    * touches again at theirs; the list's slots are stale, so `finishStep` scans the table.
    */
  private def remark(): Unit =
    rehashesSeen = open.rehashes
    listKnown = false
    touched = new Array[Long]((open.slots + 63) >> 6)
    var i = 0
    while i < touchCount do
      val slot = open.find(touchKeys(i))
      touchSlots(i) = slot
      setTouched(slot)
      i += 1

  /** Reports every open pair touching again, and no other (a step in which nothing moved: the
    * open pairs stay as they are), without looking at each: `finishStep` ends none.
    */
  def touchAllOpen(): Unit = allOpenTouched = true

  /** Describes the pair `touch` just began: the unit normal (nx, ny) from `touch`'s `a` towards
    * `b` (turned round if the pair's first shape is `b`), a point, the approach speed and the
    * normal impulse.
    */
  def describe(nx: Double, ny: Double, px: Double, py: Double, approachSpeed: Double, normalImpulse: Double): Unit =
    val sign = if lastFlipped then -1.0 else 1.0
    working.describeLast(sign * nx, sign * ny, px, py, approachSpeed, normalImpulse)

  /** Ends the step of `world`: every open pair not touched ends unless `keeps` says it may stay
    * open. Sorts the step's begins and ends by key and shows them.
    */
  def finishStep(world: World): Unit =
    judge(world, 0, beginFinish(), separation)
    endFinish()

  /** Starts `finishStep` in parts: `judge` for every item from 0 until the number returned (0
    * when every open pair stays), in ranges that may run at once, then `endFinish`.
    */
  def beginFinish(): Int =
    judgingList = listKnown
    judging = if allOpenTouched then 0 else if judgingList then listed else open.slots
    if verdicts.length < judging then verdicts = new Array[Byte](math.max(judging, 2 * verdicts.length))
    judging

  /** Judges items `from` until `until` of the finish under way (see `beginFinish`): whether each
    * open pair not touched this step may stay open (`keeps`), with `separation` for the shapes'
    * distances. Writes the items' verdicts alone, and reads the shapes and `world`: ranges may run
    * at once, each with a separation of its own, when no shape's caches are stale (see
    * `Shape.refreshCaches`: a stale shape would refresh them as it is read).
    */
  def judge(world: World, from: Int, until: Int, separation: ShapeSeparation): Unit =
    var i = from
    while i < until do
      val slot = if judgingList then listSlots(i) else i
      val key = if judgingList then listKeys(i) else open.keyAt(slot)
      val verdict =
        if key < 0 || isTouched(slot) then Settled
        else if keeps(open.firstAt(slot), open.secondAt(slot), key, world, separation) then Kept
        else Ended
      verdicts(i) = verdict.toByte
      i += 1

  /** Ends `finishStep` in parts: in the items' order, a pair kept open joins this step's touches
    * (the next step's list), a pair ended leaves the table; then the step's events are shown.
    */
  def endFinish(): Unit =
    if allOpenTouched then
      // The open pairs stay as they were, and so does the list, unless pairs began besides.
      if touchCount > 0 then listKnown = false
    else
      var i = 0
      while i < judging do
        val verdict = verdicts(i)
        if verdict != Settled then
          val slot = if judgingList then listSlots(i) else i
          val key = if judgingList then listKeys(i) else open.keyAt(slot)
          if verdict == Kept then addTouch(key, slot)
          else
            working.addEnd(key, open.firstAt(slot), open.secondAt(slot))
            open.remove(slot)
        i += 1
      // This step's touches and the pairs kept open are the open pairs: the next step's list.
      val keys = listKeys
      listKeys = touchKeys
      touchKeys = keys
      val slots = listSlots
      listSlots = touchSlots
      touchSlots = slots
      listed = touchCount
      listKnown = true
    show()
    finished = true

  /** Whether an open pair not touched this step stays open: a contact pair (never a sensor
    * pair) whose shapes are still in `world` and may still collide there, and are at most
    * [[Defaults.ContactHysteresis]] apart. A pair of shapes resting on each other may lose its
    * contact for a step (the classic step's bounce of a few micrometres, the soft step's point
    * a hair above the surface); it does not end and begin again for that.
    */
  private def keeps(first: Shape, second: Shape, key: Long, world: World, separation: ShapeSeparation): Boolean =
    !ordered && inWorld(first, (key >>> 32).toInt, world) && inWorld(second, key.toInt, world) &&
      world.enableCollisionDetection && world.enableContactEvents && first.enableContactEvents &&
      second.enableContactEvents && PairFilter.accepts(first, second) &&
      (separation.polygonsWithin(first, second, Defaults.ContactHysteresis) ||
        separation.measure(first, second) && separation.distance <= Defaults.ContactHysteresis)

  private def show(): Unit =
    val events = working
    working = shown
    shown = events
    generation += 1

  /** Puts the open pairs back as they were before this step (the step failed): its begins leave,
    * its ends come back, and the last step's events are shown again.
    */
  def undoStep(): Unit =
    listKnown = false
    val step = if finished then shown else working
    var i = 0
    while i < step.beginCount do
      val slot = open.find(step.beginKeys(i))
      if slot >= 0 then open.remove(slot)
      i += 1
    i = 0
    while i < step.endCount do
      if open.find(step.endKeys(i)) < 0 then open.insert(step.endKeys(i), step.endFirst(i), step.endSecond(i), 0)
      i += 1
    step.clear()
    if finished then
      show()
      finished = false

  /** The open pairs, sorted by key: their keys, first and second shapes. */
  def openPairs(): PairTracker.Saved =
    val keys = new Array[Long](open.size)
    val slotsOf = new Array[Int](open.size)
    var n = 0
    var slot = 0
    while slot < open.slots do
      if open.keyAt(slot) >= 0 then
        keys(n) = open.keyAt(slot)
        slotsOf(n) = slot
        n += 1
      slot += 1
    val order = Array.tabulate(n)(identity)
    sortByKey(order, keys, n, new Array[Int](n))
    PairTracker.Saved(order.map(keys), order.map(i => open.firstAt(slotsOf(i))), order.map(i => open.secondAt(slotsOf(i))))

  /** Makes the pairs of a copy taken by `openPairs` the open ones, with no events shown. */
  def restoreOpen(saved: PairTracker.Saved): Unit =
    listKnown = false
    open.clear()
    var i = 0
    while i < saved.keys.length do
      open.insert(saved.keys(i), saved.first(i), saved.second(i), 0)
      i += 1
    working.clear()
    shown.clear()
    finished = false
    generation += 1

  // ---- The events shown (the last finished step's), sorted by key when first asked for.

  /** Number of pairs begun in the last step. */
  def begins: Int =
    shown.sort()
    shown.beginCount
  /** The first shape of the k-th begin. */
  def beginFirstShape(k: Int): Shape = { shown.sort(); shown.beginFirst(shown.beginOrder(k)) }
  /** The second shape of the k-th begin. */
  def beginSecondShape(k: Int): Shape = { shown.sort(); shown.beginSecond(shown.beginOrder(k)) }
  /** One of the values `describe` gave the k-th begin (`NormalX` ... `NormalImpulse`). */
  def beginValue(k: Int, field: Int): Double = { shown.sort(); shown.beginData(shown.beginOrder(k) * DataStride + field) }
  /** Number of pairs ended in the last step. */
  def ends: Int =
    shown.sort()
    shown.endCount
  /** The first shape of the k-th end. */
  def endFirstShape(k: Int): Shape = { shown.sort(); shown.endFirst(shown.endOrder(k)) }
  /** The second shape of the k-th end. */
  def endSecondShape(k: Int): Shape = { shown.sort(); shown.endSecond(shown.endOrder(k)) }

private[sims] object PairTracker:
  // A verdict of `judge` on an item: no open pair to settle (touched this step, or an empty slot),
  // the pair kept open, or ended.
  private inline val Settled = 0
  private inline val Kept = 1
  private inline val Ended = 2

  // The values `describe` keeps per begin.
  inline val NormalX = 0
  inline val NormalY = 1
  inline val PointX = 2
  inline val PointY = 3
  inline val ApproachSpeed = 4
  inline val NormalImpulse = 5
  private inline val DataStride = 6

  /** Open pairs sorted by key (see `openPairs`): a snapshot's copy, or the pairs touching now. */
  final class Saved(val keys: Array[Long], val first: Array[Shape], val second: Array[Shape])

  /** True if `shape` is in `world` still under the join order `index` (a shape that left and
    * joined again is another pair's).
    */
  private def inWorld(shape: Shape, index: Int, world: World): Boolean =
    shape.body != null && (shape.body.world eq world) && shape.worldIndex == index

  /** The begins and ends of one step, in plain arrays reused from step to step. */
  private final class StepEvents:
    var beginKeys = new Array[Long](16)
    var beginFirst, beginSecond = new Array[Shape](16)
    var beginData = new Array[Double](16 * DataStride)
    var beginCount = 0
    var endKeys = new Array[Long](16)
    var endFirst, endSecond = new Array[Shape](16)
    var endCount = 0
    var beginOrder, endOrder, scratch = new Array[Int](16)
    private var sorted = true

    def clear(): Unit =
      sorted = true
      java.util.Arrays.fill(beginFirst.asInstanceOf[Array[AnyRef]], 0, beginCount, null)
      java.util.Arrays.fill(beginSecond.asInstanceOf[Array[AnyRef]], 0, beginCount, null)
      java.util.Arrays.fill(endFirst.asInstanceOf[Array[AnyRef]], 0, endCount, null)
      java.util.Arrays.fill(endSecond.asInstanceOf[Array[AnyRef]], 0, endCount, null)
      beginCount = 0
      endCount = 0

    def addBegin(key: Long, first: Shape, second: Shape): Unit =
      if beginCount == beginKeys.length then
        val capacity = 2 * beginCount
        beginKeys = java.util.Arrays.copyOf(beginKeys, capacity)
        beginFirst = java.util.Arrays.copyOf(beginFirst, capacity)
        beginSecond = java.util.Arrays.copyOf(beginSecond, capacity)
        beginData = java.util.Arrays.copyOf(beginData, capacity * DataStride)
      beginKeys(beginCount) = key
      beginFirst(beginCount) = first
      beginSecond(beginCount) = second
      java.util.Arrays.fill(beginData, beginCount * DataStride, (beginCount + 1) * DataStride, 0.0)
      beginCount += 1
      sorted = false

    def describeLast(nx: Double, ny: Double, px: Double, py: Double, speed: Double, impulse: Double): Unit =
      val k = (beginCount - 1) * DataStride
      beginData(k + NormalX) = nx
      beginData(k + NormalY) = ny
      beginData(k + PointX) = px
      beginData(k + PointY) = py
      beginData(k + ApproachSpeed) = speed
      beginData(k + NormalImpulse) = impulse

    def addEnd(key: Long, first: Shape, second: Shape): Unit =
      if endCount == endKeys.length then
        val capacity = 2 * endCount
        endKeys = java.util.Arrays.copyOf(endKeys, capacity)
        endFirst = java.util.Arrays.copyOf(endFirst, capacity)
        endSecond = java.util.Arrays.copyOf(endSecond, capacity)
      endKeys(endCount) = key
      endFirst(endCount) = first
      endSecond(endCount) = second
      endCount += 1
      sorted = false

    /** Orders the begins and the ends by key (once: a step nobody reads the events of skips it). */
    def sort(): Unit = if !sorted then
      sorted = true
      val needed = math.max(beginCount, endCount)
      if beginOrder.length < needed then
        beginOrder = new Array[Int](needed); endOrder = new Array[Int](needed); scratch = new Array[Int](needed)
      var i = 0
      while i < beginCount do { beginOrder(i) = i; i += 1 }
      i = 0
      while i < endCount do { endOrder(i) = i; i += 1 }
      sortByKey(beginOrder, beginKeys, beginCount, scratch)
      sortByKey(endOrder, endKeys, endCount, scratch)

  /** Sorts positions `order(0 until count)` by `keys(order(i))` (stable merge sort, `scratch` at
    * least `count` long): allocation-free.
    */
  private def sortByKey(order: Array[Int], keys: Array[Long], count: Int, scratch: Array[Int]): Unit =
    if count > 1 then
      var sorted = true
      var i = 1
      while sorted && i < count do
        if keys(order(i - 1)) > keys(order(i)) then sorted = false
        i += 1
      if !sorted then
        var from = order
        var to = scratch
        var width = 1
        while width < count do
          var start = 0
          while start < count do
            val middle = math.min(start + width, count)
            val end = math.min(start + 2 * width, count)
            var l = start
            var r = middle
            var k = start
            while k < end do
              if l < middle && (r >= end || keys(from(l)) <= keys(from(r))) then
                to(k) = from(l); l += 1
              else
                to(k) = from(r); r += 1
              k += 1
            start = end
          val t = from; from = to; to = t
          width *= 2
        if from ne order then System.arraycopy(from, 0, order, 0, count)
