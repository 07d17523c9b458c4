package sims.collision

import sims.Defaults
import sims.dynamics.{Shape, World}

/** Which pairs of shapes touch (or, for sensors, overlap) from step to step, and the begins and
  * ends of one step: the bookkeeping behind [[ContactEvents]] and [[SensorEvents]].
  *
  * A pair is identified by its two shapes' `worldIndex`es (the order they joined the world:
  * never reused, unchanged when other bodies leave), packed into a Long key. For contacts the
  * earlier shape comes first; for sensors (`ordered`) the sensor comes first. The pairs that
  * have begun and not ended are the open pairs. During a step the solver (or the sensor stage)
  * calls `touch` for every pair touching now; `finishStep` then ends every open pair that was
  * not touched, unless it may stay open (contacts only, see `keeps`), and makes the new pairs
  * open. Every begin is thus followed by exactly one end: a pair that stops touching, whose
  * shape leaves the world, stops colliding (`collidable`, filter bits, a sensor flag, a joint's
  * `collideConnected`) or whose world stops detecting collisions ends at the next step, whichever
  * solver runs it.
  *
  * Open pairs are found through a [[PairKeyMap]]; the events of a step are sorted by key, so
  * their order is the shapes' world order, never a hash order. A step with no begin and no end
  * changes nothing and allocates nothing.
  *
  * @param ordered whether the pair's order is given (sensor first), rather than by world order
  */
private[sims] final class PairTracker(ordered: Boolean):
  import PairTracker.*

  // The open pairs, and the generation before the last change (put back by `undoStep`).
  private var openKeys = new Array[Long](16)
  private var openFirst, openSecond = new Array[Shape](16)
  private var openCount = 0
  private var spareKeys = new Array[Long](16)
  private var spareFirst, spareSecond = new Array[Shape](16)
  private var spareCount = 0
  private val openIndex = PairKeyMap()
  // Per open pair: the step that last touched it.
  private var touched = new Array[Int](16)
  private var stamp = 0
  // Whether this step's `finishStep` replaced the open pairs.
  private var replaced = false

  // This step's begins, in the order found, with what the solver told of each.
  private var beginKeys = new Array[Long](16)
  private var beginFirst, beginSecond = new Array[Shape](16)
  private var beginData = new Array[Double](16 * DataStride)
  private var beginCount = 0
  private val beginIndex = PairKeyMap()
  private var lastFlipped = false

  // This step's ends.
  private var endKeys = new Array[Long](16)
  private var endFirst, endSecond = new Array[Shape](16)
  private var endCount = 0

  // The events' order: positions sorted by key.
  private var beginOrder, endOrder, scratch = new Array[Int](16)

  private val separation = ShapeSeparation()

  /** Number of open pairs. */
  def openPairs: Int = openCount

  /** The first shape of open pair i (in no particular order; see `openSorted`). */
  def openFirstShape(i: Int): Shape = openFirst(i)

  /** The second shape of open pair i. */
  def openSecondShape(i: Int): Shape = openSecond(i)

  /** The open pairs' positions, sorted by key. */
  def openSorted(): Array[Int] =
    val order = Array.tabulate(openCount)(identity)
    sortByKey(order, openKeys, openCount, new Array[Int](openCount))
    order

  /** Starts a step: no pair touched yet, no begins, no ends. */
  def beginStep(): Unit =
    stamp += 1
    beginCount = 0
    beginIndex.clear()
    endCount = 0
    replaced = false

  /** Reports that shapes `a` and `b` touch now; true if that begins their pair (it was not open
    * and not reported yet this step): the caller then describes it with `describe`.
    */
  def touch(a: Shape, b: Shape): Boolean =
    lastFlipped = !ordered && b.worldIndex < a.worldIndex
    val first = if lastFlipped then b else a
    val second = if lastFlipped then a else b
    val key = keyOf(first, second)
    val open = openIndex.get(key)
    if open >= 0 then
      touched(open) = stamp
      false
    else if beginIndex.get(key) >= 0 then false
    else
      if beginCount == beginKeys.length then growBegins()
      beginKeys(beginCount) = key
      beginFirst(beginCount) = first
      beginSecond(beginCount) = second
      java.util.Arrays.fill(beginData, beginCount * DataStride, (beginCount + 1) * DataStride, 0.0)
      beginIndex.put(key, beginCount)
      beginCount += 1
      true

  /** Describes the pair `touch` just began: the unit normal (nx, ny) from `touch`'s `a` towards
    * `b` (turned round if the pair's first shape is `b`), a point, the approach speed and the
    * normal impulse.
    */
  def describe(nx: Double, ny: Double, px: Double, py: Double, approachSpeed: Double, normalImpulse: Double): Unit =
    val k = (beginCount - 1) * DataStride
    val sign = if lastFlipped then -1.0 else 1.0
    beginData(k + NormalX) = sign * nx
    beginData(k + NormalY) = sign * ny
    beginData(k + PointX) = px
    beginData(k + PointY) = py
    beginData(k + ApproachSpeed) = approachSpeed
    beginData(k + NormalImpulse) = normalImpulse

  /** Ends the step of `world`: every open pair not touched ends unless `keeps` says it may stay
    * open; the pairs begun become open. Sorts this step's begins and ends by key.
    */
  def finishStep(world: World): Unit =
    var i = 0
    while i < openCount do
      if touched(i) != stamp then
        if keeps(i, world) then touched(i) = stamp else addEnd(i)
      i += 1
    if endCount > 0 || beginCount > 0 then replaceOpen()
    sortEvents()

  /** Whether open pair i, not touched this step, stays open: a contact pair (never a sensor
    * pair) whose shapes are still in `world` and may still collide there, and are at most
    * [[Defaults.ContactHysteresis]] apart. A pair of shapes resting on each other may lose its
    * contact for a step (the classic step's bounce of a few micrometres, the soft step's point
    * a hair above the surface); it does not end and begin again for that.
    */
  private def keeps(i: Int, world: World): Boolean =
    if ordered then false
    else
      val first = openFirst(i)
      val second = openSecond(i)
      val key = openKeys(i)
      inWorld(first, (key >>> 32).toInt, world) && inWorld(second, key.toInt, world) &&
        world.enableCollisionDetection && PairFilter.accepts(first, second) &&
        separation.measure(first, second) && separation.distance <= Defaults.ContactHysteresis

  private def addEnd(i: Int): Unit =
    if endCount == endKeys.length then
      val capacity = 2 * endCount
      endKeys = java.util.Arrays.copyOf(endKeys, capacity)
      endFirst = java.util.Arrays.copyOf(endFirst, capacity)
      endSecond = java.util.Arrays.copyOf(endSecond, capacity)
    endKeys(endCount) = openKeys(i)
    endFirst(endCount) = openFirst(i)
    endSecond(endCount) = openSecond(i)
    endCount += 1

  /** The open pairs that stay (touched or kept), then the begun ones, into the spare
    * generation, which becomes the open one.
    */
  private def replaceOpen(): Unit =
    val needed = openCount + beginCount
    if spareKeys.length < needed then
      val capacity = math.max(needed, 2 * spareKeys.length)
      spareKeys = new Array[Long](capacity)
      spareFirst = new Array[Shape](capacity)
      spareSecond = new Array[Shape](capacity)
    var n = 0
    var i = 0
    while i < openCount do
      if touched(i) == stamp then // touched or kept: stays open
        spareKeys(n) = openKeys(i)
        spareFirst(n) = openFirst(i)
        spareSecond(n) = openSecond(i)
        n += 1
      i += 1
    i = 0
    while i < beginCount do
      spareKeys(n) = beginKeys(i)
      spareFirst(n) = beginFirst(i)
      spareSecond(n) = beginSecond(i)
      n += 1
      i += 1
    spareCount = n
    swap()
    // The generation left behind keeps its shapes for `undoStep` until the next change.
    replaced = true

  private def swap(): Unit =
    val (keys, first, second, count) = (openKeys, openFirst, openSecond, openCount)
    openKeys = spareKeys; openFirst = spareFirst; openSecond = spareSecond; openCount = spareCount
    spareKeys = keys; spareFirst = first; spareSecond = second; spareCount = count
    if touched.length < openKeys.length then touched = new Array[Int](openKeys.length)
    indexOpen()

  private def indexOpen(): Unit =
    openIndex.clear()
    var i = 0
    while i < openCount do
      openIndex.put(openKeys(i), i)
      touched(i) = 0
      i += 1

  /** Puts back the open pairs as they were before this step (the step failed after
    * `finishStep`); the step's begins and ends are then forgotten by the next `beginStep`.
    */
  def undoStep(): Unit =
    if replaced then
      swap()
      replaced = false

  /** A copy of the open pairs, for a snapshot of the world. */
  def copyOpen(): PairTracker.Saved =
    PairTracker.Saved(java.util.Arrays.copyOf(openKeys, openCount), java.util.Arrays.copyOf(openFirst, openCount),
      java.util.Arrays.copyOf(openSecond, openCount))

  /** Makes the pairs of a copy taken by `copyOpen` the open ones; this step's events are forgotten. */
  def restoreOpen(saved: PairTracker.Saved): Unit =
    val n = saved.keys.length
    if openKeys.length < n then
      openKeys = new Array[Long](n); openFirst = new Array[Shape](n); openSecond = new Array[Shape](n)
      touched = new Array[Int](n)
    System.arraycopy(saved.keys, 0, openKeys, 0, n)
    System.arraycopy(saved.first, 0, openFirst, 0, n)
    System.arraycopy(saved.second, 0, openSecond, 0, n)
    java.util.Arrays.fill(openFirst.asInstanceOf[Array[AnyRef]], n, openFirst.length, null)
    java.util.Arrays.fill(openSecond.asInstanceOf[Array[AnyRef]], n, openSecond.length, null)
    openCount = n
    indexOpen()
    beginStep()
    replaced = false

  // ---- This step's events, sorted by key (after `finishStep`).

  /** Number of pairs begun this step. */
  def begins: Int = beginCount
  /** The first shape of the k-th begin. */
  def beginFirstShape(k: Int): Shape = beginFirst(beginOrder(k))
  /** The second shape of the k-th begin. */
  def beginSecondShape(k: Int): Shape = beginSecond(beginOrder(k))
  /** One of the values `describe` gave the k-th begin (`NormalX` ... `NormalImpulse`). */
  def beginValue(k: Int, field: Int): Double = beginData(beginOrder(k) * DataStride + field)
  /** Number of pairs ended this step. */
  def ends: Int = endCount
  /** The first shape of the k-th end. */
  def endFirstShape(k: Int): Shape = endFirst(endOrder(k))
  /** The second shape of the k-th end. */
  def endSecondShape(k: Int): Shape = endSecond(endOrder(k))

  private def sortEvents(): Unit =
    val needed = math.max(beginCount, endCount)
    if beginOrder.length < needed then
      beginOrder = new Array[Int](needed); endOrder = new Array[Int](needed); scratch = new Array[Int](needed)
    var i = 0
    while i < beginCount do { beginOrder(i) = i; i += 1 }
    i = 0
    while i < endCount do { endOrder(i) = i; i += 1 }
    sortByKey(beginOrder, beginKeys, beginCount, scratch)
    sortByKey(endOrder, endKeys, endCount, scratch)

  private def growBegins(): Unit =
    val capacity = 2 * beginCount
    beginKeys = java.util.Arrays.copyOf(beginKeys, capacity)
    beginFirst = java.util.Arrays.copyOf(beginFirst, capacity)
    beginSecond = java.util.Arrays.copyOf(beginSecond, capacity)
    beginData = java.util.Arrays.copyOf(beginData, capacity * DataStride)

private[sims] object PairTracker:
  // The values `describe` keeps per begin.
  inline val NormalX = 0
  inline val NormalY = 1
  inline val PointX = 2
  inline val PointY = 3
  inline val ApproachSpeed = 4
  inline val NormalImpulse = 5
  private inline val DataStride = 6

  /** A copy of a tracker's open pairs (see `copyOpen`). */
  final class Saved(val keys: Array[Long], val first: Array[Shape], val second: Array[Shape])

  /** The key of the pair (first, second): their join orders, the first's in the high half. */
  def keyOf(first: Shape, second: Shape): Long =
    (first.worldIndex.toLong << 32) | (second.worldIndex.toLong & 0xffffffffL)

  /** True if `shape` is in `world` still under the join order `index` (a shape that left and
    * joined again is another pair's).
    */
  private def inWorld(shape: Shape, index: Int, world: World): Boolean =
    shape.body != null && (shape.body.world eq world) && shape.worldIndex == index

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
