package sims.collision.broadphase

import sims.collision.PairBuffer
import sims.dynamics.Shape

/** Candidate pairs kept from step to step, for the soft step: the grid searches for a shape's
  * partners only when the shape has left the bounds it had at its last search, so a scene at
  * rest finds its pairs without a search (the idea of Box2D's broadphase, whose proxies have
  * "fat" bounds and are queried again only when they leave them).
  *
  * Each moving shape's bounds are held enlarged by a margin ([[KeptPairs.FatFraction]] of their
  * smaller side; none for a fixed body's). The kept pairs are those whose enlarged bounds
  * overlap. While a shape's bounds of the step lie within its enlarged ones, its pairs whose
  * bounds of the step overlap are all among the kept ones. A step's pairs are the kept pairs
  * whose bounds overlap now and that the filter accepts: the same pairs as the grid's. They come
  * in one order whatever the history: by their second shape, then by their first (by index), so
  * that a step's result depends on the world's state alone.
  *
  * When shapes left their enlarged bounds, or slowed down so much that those are over
  * [[KeptPairs.MostFatScale]] times as wide or as tall as their bounds, only their partners are
  * searched (their pairs are dropped and found again, with bounds enlarged afresh), unless more
  * than one in [[KeptPairs.MostMovedShare]] did: then the
  * grid searches for all pairs, shared out among the workers when there are several. A search
  * that finds more than its limit of kept pairs gives way to the grid's search of the step's own
  * bounds, which alone decides whether the step has too many pairs.
  *
  * The filter: a pair of two plain shapes (see `UniformGrid.kindOf`) is judged at the search, and
  * stays judged while both shapes keep their kinds (a shape whose kind changes is searched
  * again); a pair with any other shape is kept if the shapes belong to different bodies, and
  * judged again each step (the filter's settings can change at any time). Any change of the
  * world's shapes or bodies (its revision) starts afresh.
  */
private[sims] final class KeptPairs:
  import KeptPairs.before

  // Per shape, from its last search: its enlarged bounds (min x, min y, max x, max y; NaN for a
  // shape the grid left out) and its kind for the filter.
  private var fat = new Array[Double](0)
  private var kinds = new Array[Byte](0)
  // The shapes that left their enlarged bounds this step: marked, and listed in index order.
  private var marks = new Array[Boolean](0)
  private var movedShapes = new Array[Int](0)
  // The kept pairs, by second shape, then first; and room to merge into.
  private var firsts, seconds = new Array[Int](0)
  private var size = 0
  private var mergedFirsts, mergedSeconds = new Array[Int](0)
  // The grid's pairs of a full search, the moved shapes' partners, and sort keys for them.
  private val searched = PairBuffer()
  private val found = PairBuffer()
  found.keeps = true
  private var sortKeys = new Array[Double](0)
  private var shapes: Array[Shape] = null
  private var count = 0
  private var revision = -1L
  private var valid = false
  // The grid's own bounds while it searches with the enlarged ones.
  private var own: Array[Double] = null

  /** Searches since this object was made, and how many of them were full (for the tests). */
  var searches, fullSearches: Long = 0

  /** Brings the kept pairs up to date with the grid's update of this step (its `boundsOf` done)
    * in a world at `revision`, at most `limit` kept pairs (past it the search fails, naming
    * `limitName`). Returns true when they are: nothing left its enlarged bounds, or a few shapes
    * did and their partners alone were searched. Returns false when the grid must search in
    * full: the grid then holds the enlarged bounds, and the caller runs its `endUpdate` and pair
    * search (serial or shared) into `buffer`, then `searchDone(grid)`, and in a `finally`
    * `endSearch(grid)`.
    */
  def update(grid: UniformGrid, revision: Long, limit: Int, limitName: String): Boolean =
    val same = valid && (grid.shapeArray eq shapes) && grid.shapeCount == count && revision == this.revision
    if same && within(grid) then true
    else
      valid = false
      val n = grid.shapeCount
      if !same then forget(n)
      shapes = grid.shapeArray
      count = n
      this.revision = revision
      val moved = enlarge(grid)
      own = grid.boxes
      grid.boxes = fat
      grid.keeping = true
      searches += 1
      if same && moved * KeptPairs.MostMovedShare <= n then
        try
          grid.endUpdate()
          grid.fillFineGrid()
          removeMarked()
          found.clear(shapes)
          found.limit = limit - size
          found.limitName = limitName
          var k = 0
          while k < moved do
            grid.partnersOf(movedShapes(k), marks, found)
            k += 1
          sortRange(found, 0, found.size)
          merge(found.size)
          valid = true
        finally
          endSearch(grid)
          unmark(moved)
        true
      else
        fullSearches += 1
        unmark(moved)
        searched.keeps = true
        searched.limit = limit
        searched.limitName = limitName
        false

  /** The buffer for the grid's full search (see `update`). */
  def buffer: PairBuffer = searched

  /** Takes the full search's pairs (see `update`) as the kept ones. */
  def searchDone(grid: UniformGrid): Unit =
    val n = searched.size
    ensureRoom(n)
    var k = 0
    while k < n do
      firsts(k) = searched.firstIndex(k)
      seconds(k) = searched.secondIndex(k)
      k += 1
    size = n
    // The grid's pairs come by second shape, each shape's partners in the order of its cells
    // (each group's firsts sorted: a falling ball's bounds, stretched by its sweep, can meet a
    // hundred partners, too many for an insertion sort), then the large shapes' pairs (sorted,
    // merged).
    val split = math.min(grid.largeFrom, n)
    var from = 0
    while from < split do
      val second = seconds(from)
      var until = from + 1
      while until < split && seconds(until) == second do until += 1
      if until - from > 1 then java.util.Arrays.sort(firsts, from, until)
      from = until
    if split < n then
      sortRange(searched, split, n)
      size = split
      merge(n - split)
    valid = true

  /** After a search that met more than its limit of kept pairs (see `update`, its pairs lost): the
    * grid's pairs of this update's own bounds, at most `maxPairs` (past it the search fails,
    * naming `limitName`), taken for this step only (the next searches in full).
    */
  def searchTight(grid: UniformGrid, maxPairs: Int, limitName: String): Unit =
    endSearch(grid)
    searched.keeps = false
    searched.limit = maxPairs
    searched.limitName = limitName
    size = 0
    grid.endUpdate()
    grid.findPairs(searched, inGridOrder = false)
    searchDone(grid)
    valid = false

  /** Gives the grid its own bounds back after a search (done or failed). */
  def endSearch(grid: UniformGrid): Unit =
    if own != null then
      grid.boxes = own
      own = null
    grid.keeping = false

  /** Makes `pairs` this step's pairs: the kept pairs whose bounds in the grid overlap and that
    * the filter accepts (with the limit and name `pairs` has). The grid's fine grid is then not
    * built for this update (a query builds its own).
    */
  def emit(grid: UniformGrid, pairs: PairBuffer): Unit =
    emitRange(grid, 0, size, pairs)
    endEmit(grid)

  /** How many pairs are kept: `emit` looks at each. */
  def keptCount: Int = size

  /** `emit`'s work for the kept pairs `from` until `until` (in the kept order): makes `out` those
    * whose bounds overlap and that the filter accepts. Several threads may run it at once, for
    * ranges of their own into buffers of their own: appended in the ranges' order, the buffers
    * hold `emit`'s pairs. Then `endEmit`.
    */
  def emitRange(grid: UniformGrid, from: Int, until: Int, out: PairBuffer): Unit =
    out.clear(shapes)
    var k = from
    while k < until do
      val j = firsts(k)
      val i = seconds(k)
      if grid.overlap(j, i) && grid.acceptsKept(j, i) then out.add(j, i)
      k += 1

  /** Ends an emission of the kept pairs (see `emitRange`). */
  def endEmit(grid: UniformGrid): Unit =
    grid.pairTests += size
    grid.gridUnused()

  private def within(grid: UniformGrid): Boolean =
    val boxes = grid.boxes
    var i = 0
    var inside = true
    while inside && i < count do
      val b = 4 * i
      inside =
        if grid.ignored(i) then fat(b) != fat(b)
        else withinFat(boxes, b) && !oversized(boxes, b) && kinds(i) == grid.kind(i)
      i += 1
    inside

  /** New enlarged bounds for each shape that left its own or whose kind changed, each marked and
    * listed in `movedShapes`; returns how many.
    */
  private def enlarge(grid: UniformGrid): Int =
    val boxes = grid.boxes
    var moved = 0
    var i = 0
    while i < count do
      val b = 4 * i
      if grid.ignored(i) then
        if fat(b) == fat(b) then
          fat(b) = Double.NaN; fat(b + 1) = Double.NaN; fat(b + 2) = Double.NaN; fat(b + 3) = Double.NaN
          moved = mark(i, moved)
      else if !withinFat(boxes, b) || oversized(boxes, b) || kinds(i) != grid.kind(i) then
        val margin =
          if grid.body(i).immovable then 0.0
          else KeptPairs.FatFraction * math.min(boxes(b + 2) - boxes(b), boxes(b + 3) - boxes(b + 1))
        fat(b) = boxes(b) - margin; fat(b + 1) = boxes(b + 1) - margin
        fat(b + 2) = boxes(b + 2) + margin; fat(b + 3) = boxes(b + 3) + margin
        kinds(i) = grid.kind(i)
        moved = mark(i, moved)
      i += 1
    moved

  /** Whether the bounds at `b` in `boxes` lie within the enlarged ones at `b` (false for NaN). */
  private inline def withinFat(boxes: Array[Double], b: Int): Boolean =
    fat(b) <= boxes(b) && fat(b + 1) <= boxes(b + 1) && boxes(b + 2) <= fat(b + 2) && boxes(b + 3) <= fat(b + 3)

  /** Whether the enlarged bounds at `b` are more than [[KeptPairs.MostFatScale]] times as wide or
    * as tall as the bounds at `b` in `boxes`: the shape slowed down since its search, whose bounds
    * its sweep then stretched, and its kept partners are mostly shapes it no longer meets.
    */
  private inline def oversized(boxes: Array[Double], b: Int): Boolean =
    fat(b + 2) - fat(b) > KeptPairs.MostFatScale * (boxes(b + 2) - boxes(b)) ||
      fat(b + 3) - fat(b + 1) > KeptPairs.MostFatScale * (boxes(b + 3) - boxes(b + 1))

  /** Makes `pairs` this step's pairs from the grid's update (its `boundsOf` done) in a world at
    * `revision`, with at most `maxPairs` of them (past it the step fails, naming `limitName`):
    * `update`, `search` into `buffer` when the grid must search in full, and the grid's search of
    * the step's own bounds when the kept pairs would pass twice `maxPairs`; then the search's
    * `emit`.
    */
  def pairsOf(grid: UniformGrid, revision: Long, maxPairs: Int, limitName: String, pairs: PairBuffer,
      search: KeptPairs.Search): Unit =
    val found =
      try
        update(grid, revision, KeptPairs.limitFor(maxPairs), limitName) || {
          search.run(grid, searched)
          searchDone(grid)
          true
        }
      catch case _: PairBuffer.TooManyPairs => false
      finally endSearch(grid)
    if !found then searchTight(grid, maxPairs, limitName)
    search.emit(this, grid, pairs)

  private def mark(i: Int, moved: Int): Int =
    marks(i) = true
    movedShapes(moved) = i
    moved + 1

  private def unmark(moved: Int): Unit =
    var k = 0
    while k < moved do
      marks(movedShapes(k)) = false
      k += 1

  /** Drops the kept pairs of the marked shapes; the others keep their order. */
  private def removeMarked(): Unit =
    var n = 0
    var k = 0
    while k < size do
      val f = firsts(k)
      val s = seconds(k)
      if !marks(f) && !marks(s) then
        firsts(n) = f
        seconds(n) = s
        n += 1
      k += 1
    size = n

  /** Sorts pairs `from` until `until` of `pairs` in the kept order, in `sortKeys`: a Double holds
    * second * 2^31 + first exactly, and sorts as the pair does.
    */
  private def sortRange(pairs: PairBuffer, from: Int, until: Int): Unit =
    if sortKeys.length < until - from then sortKeys = new Array[Double](math.max(until - from, 2 * sortKeys.length))
    var k = from
    while k < until do
      sortKeys(k - from) = pairs.secondIndex(k) * KeptPairs.KeyScale + pairs.firstIndex(k)
      k += 1
    java.util.Arrays.sort(sortKeys, 0, until - from)

  /** Merges the first `extra` pairs sorted in `sortKeys` into the kept ones. */
  private def merge(extra: Int): Unit =
    val total = size + extra
    if mergedFirsts.length < total then
      mergedFirsts = new Array[Int](math.max(total, 2 * mergedFirsts.length))
      mergedSeconds = new Array[Int](mergedFirsts.length)
    var a = 0
    var b = 0
    var out = 0
    while out < total do
      val takeKept =
        b == extra || a < size && {
          val key = sortKeys(b)
          val s = (key / KeptPairs.KeyScale).toInt
          before(firsts(a), seconds(a), KeptPairs.firstOf(key, s), s)
        }
      if takeKept then
        mergedFirsts(out) = firsts(a); mergedSeconds(out) = seconds(a)
        a += 1
      else
        val key = sortKeys(b)
        val s = (key / KeptPairs.KeyScale).toInt
        mergedFirsts(out) = KeptPairs.firstOf(key, s); mergedSeconds(out) = s
        b += 1
      out += 1
    val f = firsts; firsts = mergedFirsts; mergedFirsts = f
    val s = seconds; seconds = mergedSeconds; mergedSeconds = s
    size = total

  private def ensureRoom(n: Int): Unit =
    if firsts.length < n then
      firsts = new Array[Int](math.max(n, 2 * firsts.length))
      seconds = new Array[Int](firsts.length)

  // A new set of shapes: every shape gets new enlarged bounds (and the grid searches in full).
  private def forget(n: Int): Unit =
    if kinds.length < n then
      fat = new Array[Double](4 * n)
      kinds = new Array[Byte](n)
      marks = new Array[Boolean](n)
      movedShapes = new Array[Int](n)
    java.util.Arrays.fill(fat, Double.NaN)
    size = 0

private[sims] object KeptPairs:
  /** The grid's full search for the kept pairs, and their emission, on one thread or shared out
    * (see `pairsOf`).
    */
  trait Search:
    /** Runs the search of `grid` into `buffer`: its `endUpdate` and pair search. */
    def run(grid: UniformGrid, buffer: PairBuffer): Unit

    /** Makes `pairs` the step's pairs from `kept`: its `emit`, or the same in ranges shared out. */
    def emit(kept: KeptPairs, grid: UniformGrid, pairs: PairBuffer): Unit = kept.emit(grid, pairs)

  /** A moving shape's bounds are held enlarged by this fraction of their smaller side: a resting
    * shape's jitter stays far within it, and a ball in a pile gains few kept partners.
    */
  val FatFraction = 0.1

  /** A shape whose enlarged bounds grew more than this many times as wide or as tall as its bounds
    * is searched again with bounds enlarged afresh (enlarged afresh, they are at most 1 + 2
    * FatFraction times as wide and as tall).
    */
  val MostFatScale = 2.0

  /** When more than one shape in this many left its enlarged bounds, the grid searches in full. */
  val MostMovedShare = 4

  /** 2^31: a pair's sort key is second * KeyScale + first. */
  private val KeyScale = 2147483648.0

  /** The first shape of the pair of sort key `key` whose second shape is `second`. */
  private inline def firstOf(key: Double, second: Int): Int = (key - second * KeyScale).toInt

  /** Pair (f1, s1) comes before (f2, s2) in the kept order: by second shape, then by first. */
  private inline def before(f1: Int, s1: Int, f2: Int, s2: Int): Boolean = s1 < s2 || s1 == s2 && f1 < f2

  /** The most kept pairs for a step limited to `maxPairs`: twice as many (the enlarged bounds
    * overlap more often, and pairs the filter turns down are kept too).
    */
  def limitFor(maxPairs: Int): Int = if maxPairs > Int.MaxValue / 2 then Int.MaxValue else 2 * maxPairs
