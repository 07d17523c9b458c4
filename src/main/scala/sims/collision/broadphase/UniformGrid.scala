package sims.collision.broadphase

import scala.collection.mutable.ArrayBuffer
import sims.Defaults
import sims.collision.{PairBuffer, PairFilter}
import sims.dynamics.{Body, Shape}

/** SiMS's grid broadphase (docs/collisions.md): square cells of side `gridSide`; two shapes are a
  * candidate pair when they share a cell, their bounds overlap and [[PairFilter]] accepts them.
  * Each unordered pair is reported once: for each shape in world order, its partners among the
  * earlier shapes, cell by cell of the shape's cells (x, then y), and within a cell the most
  * recently added partner first (a pair is reported in the cell that holds the lower-left
  * corner of the two bounds' overlap).
  *
  * How it is computed: with the default 2 m cells a ball pit puts about 80 balls in a cell, so
  * partners are found in an internal finer grid (cells 1.5 times the shapes' mean extent),
  * then sorted into the coarse grid's order: the same pairs in the same order, faster. Shapes
  * covering more than 64 fine cells ("wide") are tested against every other grid shape, and
  * shapes covering more than [[Defaults.LargeShapeCells]] coarse cells ("large", a huge
  * ground) against every shape, so one big shape does not fill thousands of cells.
  */
private[sims] final class UniformGrid extends Broadphase:
  import UniformGrid.*

  private var _gridSide = Defaults.GridSide

  /** Side of a cell, m. */
  def gridSide: Double = _gridSide

  /** Sets the cell side; must be positive and finite. */
  def gridSide_=(side: Double): Unit = _gridSide = Shape.requirePositive("gridSide", side)

  private var shapes = Array.empty[Shape]
  private var count = 0
  // Per shape, from the last update: its enlarged bounds, its placement, the coarse and fine
  // cells of its bounds' lower-left corner and the fine cells of its upper-right one. Cell
  // functions are monotonic, so the cell of the corner of two bounds' overlap, cell(max(a, b)),
  // is max(cell(a), cell(b)): computed once per shape instead of once per candidate.
  // The bounds are four doubles a shape in one array, min x, min y, max x, max y, and the fine
  // cells four Ints a shape, x0, y0, x1, y1: the pair search reads a partner's together, one
  // cache line or two where four arrays took four.
  private[broadphase] var boxes = new Array[Double](0)
  private var placement = new Array[Byte](0)
  // Per shape, from the last update: its body, and whether the filter's answer for it follows
  // from that alone (see `filterKind`): a pair of two such shapes is judged from these arrays,
  // without reading the shapes and bodies (a cache miss each, for every candidate).
  private var owner = new Array[Body](0)
  private var filterKind = new Array[Byte](0)
  private var fines = new Array[Int](0)
  // Coarse cells as Longs: floor(coordinate / gridSide) is exact in a Long for any coordinate
  // up to 1.8e19 gridSides, so far from the origin pairs keep SiMS's order (in an Int it
  // saturates beyond 2^31 cells, 4.3e9 m with 2 m cells). Only the coarse grid's order reads
  // them: `findPairs` fills them when it sorts (on Scala.js a Double to Long allocates).
  private var coarseX0, coarseY0 = new Array[Long](0)
  private val wide = ArrayBuffer.empty[Int]
  private val large = ArrayBuffer.empty[Int]
  // A large shape's partners from the fine cells (see `partnersInCells`).
  private var found = new Array[Int](0)
  private val grid = CellGrid()
  private var perFine = 1.0 // 1 / the fine cell side
  // The fine grid's cells count from the lower-left corner of the fine shapes' bounds, so that
  // a scene far from the origin gets cell indices as small as one near it (with cells counted
  // from the origin they saturate at the Int range beyond about 6e8 m, and every shape there
  // lands in one cell: quadratic). Pair order does not depend on the fine grid.
  private var originX, originY = 0.0
  private var gridBuilt = false
  // While `KeptPairs` searches its pairs: a pair with a shape whose filter is not plain is kept
  // whatever the filter says now (it is asked again each step, and its settings may change).
  private[broadphase] var keeping = false
  // Where the large shapes' pairs began in the last `findPairs` or `endShared` (the pairs before
  // them come shape by shape: grouped by their second shape, in index order).
  private[broadphase] var largeFrom = 0
  // Partners of the shape being placed: their order keys, and its coarse cells.
  private var groupKeys = new Array[Long](16)
  private var groupSize = 0
  private var groupX0, groupY0 = 0L
  private var groupRows = 0L
  private var sorted = true
  // Query bookkeeping: the last query that found each shape.
  private var foundStamp = new Array[Int](0)
  private var queryStamp = 0
  private val foundIndices = ArrayBuffer.empty[Int]
  // The box around the bounds of the shapes in the fine grid: a ray's walk is clipped to it.
  private var fineMinX, fineMinY, fineMaxX, fineMaxY = 0.0
  // The settings of the update under way (see `beginUpdate`).
  private var updateMargin, updateSweep = 0.0
  private var updateEveryShape = false
  // A shared `endUpdate` and grid build: ranges of shapes (see `beginFineCells`), and per range
  // its wide shapes, its fine shapes' entries in the grid (then: the first entry) and their box.
  private var fineRanges = 1
  private var rangeFrom, rangeUntil, rangeWide, rangeEntries = new Array[Int](0)
  private var rangeBox = new Array[Double](0)

  def update(shapes: Array[Shape], margin: Double): Unit = update(shapes, margin, 0, everyShape = false)

  /** `update`, each shape's bounds also enlarged by how far its body's points can move in
    * `sweep` seconds at their current speed (|v| + |w| extent): a solver that makes contacts
    * before shapes touch (the soft step) then finds the pairs that can meet within the step.
    * With `everyShape`, shapes that are not collidable and sensors are taken too (for queries); otherwise
    * they are left out (they collide with nothing).
    */
  def update(shapes: Array[Shape], margin: Double, sweep: Double, everyShape: Boolean): Unit =
    beginUpdate(shapes, margin, sweep, everyShape)
    boundsOf(0, count)
    endUpdate()

  /** Starts `update` shared among threads: `boundsOf` may then run for ranges of the shapes on
    * several threads at once, after which `endUpdate` ends it (the same grid as `update`).
    */
  def beginUpdate(shapes: Array[Shape], margin: Double, sweep: Double, everyShape: Boolean): Unit =
    this.shapes = shapes
    count = shapes.length
    ensureCapacity(count)
    updateMargin = margin
    updateSweep = sweep
    updateEveryShape = everyShape

  /** The enlarged bounds, coarse cells and placement (ignored, large or fine) of shapes `from`
    * until `until` of this update. Writes their slots only: ranges may run at once.
    */
  def boundsOf(from: Int, until: Int): Unit =
    val side = _gridSide
    val margin = updateMargin
    val sweep = updateSweep
    var i = from
    while i < until do
      val s = shapes(i)
      if (!s.collidable || s.sensor) && !updateEveryShape then placement(i) = Ignored
      else
        if owner(i) ne s.body then owner(i) = s.body // no write barrier for last step's body
        filterKind(i) = kindOf(s)
        val reach =
          if sweep == 0 then margin
          else
            val b = s.body
            margin + sweep * (math.sqrt(b.vx * b.vx + b.vy * b.vy) + math.abs(b.w) * b.extent)
        val x0 = s.minX - reach; val y0 = s.minY - reach
        val x1 = s.maxX + reach; val y1 = s.maxY + reach
        boxes(4 * i) = x0; boxes(4 * i + 1) = y0; boxes(4 * i + 2) = x1; boxes(4 * i + 3) = y1
        placement(i) =
          if (cellIndex(x1, side) - cellIndex(x0, side) + 1) * (cellIndex(y1, side) - cellIndex(y0, side) + 1) >
              Defaults.LargeShapeCells
          then Large
          else Fine
      i += 1

  /** Ends the update from the shapes' bounds: the large shapes, the fine grid's cells (from the
    * mean extent of the others) and each fine shape's fine cells.
    */
  def endUpdate(): Unit =
    beginFineCells(1)
    fineCellsOf(0, 0, count)
    endFineCells()

  /** Starts `endUpdate` shared among threads: the large shapes and the fine cells' size, here;
    * then `fineCellsOf` for `ranges` ranges of the shapes in order (they may run at once), then
    * `endFineCells` (the same grid as `endUpdate`).
    */
  def beginFineCells(ranges: Int): Unit =
    val side = _gridSide
    large.clear()
    wide.clear()
    // The large shapes, and the mean extent of the others, in shape order.
    var extentSum = 0.0
    var counted = 0
    originX = Double.PositiveInfinity
    originY = Double.PositiveInfinity
    var i = 0
    while i < count do
      val p = placement(i)
      if p == Large then large += i
      else if p == Fine then
        val x0 = boxMinX(i); val y0 = boxMinY(i)
        extentSum += math.max(boxMaxX(i) - x0, boxMaxY(i) - y0)
        counted += 1
        if x0 < originX then originX = x0
        if y0 < originY then originY = y0
      i += 1
    if counted == 0 then
      originX = 0
      originY = 0
    val fine =
      val mean = if counted == 0 then side else extentSum / counted * FineCellPerExtent
      if mean > 0 && mean <= side then mean else side
    // Fine cells by multiplication: any consistent cell function serves the internal grid.
    perFine = 1 / fine
    fineRanges = ranges
    if rangeFrom.length < ranges then
      rangeFrom = new Array[Int](ranges); rangeUntil = new Array[Int](ranges)
      rangeWide = new Array[Int](ranges); rangeEntries = new Array[Int](ranges)
      rangeBox = new Array[Double](4 * ranges)

  /** The fine cells of shapes `from` until `until`, range `range` of `beginFineCells`: writes
    * their slots and the range's own only.
    */
  def fineCellsOf(range: Int, from: Int, until: Int): Unit =
    var minX, minY = Double.PositiveInfinity
    var maxX, maxY = Double.NegativeInfinity
    var wides = 0
    var entries = 0
    var i = from
    while i < until do
      if placement(i) == Fine then
        fines(4 * i) = fineCell(boxMinX(i) - originX, perFine); fines(4 * i + 2) = fineCell(boxMaxX(i) - originX, perFine)
        fines(4 * i + 1) = fineCell(boxMinY(i) - originY, perFine); fines(4 * i + 3) = fineCell(boxMaxY(i) - originY, perFine)
        val cells = cellCount(fineX0(i), fineX1(i), fineY0(i), fineY1(i))
        if cells > FineShapeCells then
          placement(i) = Wide
          wides += 1
        else
          entries += cells.toInt
          minX = math.min(minX, boxMinX(i)); minY = math.min(minY, boxMinY(i))
          maxX = math.max(maxX, boxMaxX(i)); maxY = math.max(maxY, boxMaxY(i))
      i += 1
    rangeFrom(range) = from
    rangeUntil(range) = until
    rangeWide(range) = wides
    rangeEntries(range) = entries
    rangeBox(4 * range) = minX; rangeBox(4 * range + 1) = minY
    rangeBox(4 * range + 2) = maxX; rangeBox(4 * range + 3) = maxY

  /** Ends a shared `endUpdate`: the box of the fine shapes (minima and maxima: the same in any
    * order) and the wide shapes, in shape order.
    */
  def endFineCells(): Unit =
    fineMinX = Double.PositiveInfinity; fineMinY = Double.PositiveInfinity
    fineMaxX = Double.NegativeInfinity; fineMaxY = Double.NegativeInfinity
    var r = 0
    while r < fineRanges do
      fineMinX = math.min(fineMinX, rangeBox(4 * r)); fineMinY = math.min(fineMinY, rangeBox(4 * r + 1))
      fineMaxX = math.max(fineMaxX, rangeBox(4 * r + 2)); fineMaxY = math.max(fineMaxY, rangeBox(4 * r + 3))
      if rangeWide(r) > 0 then
        var i = rangeFrom(r)
        while i < rangeUntil(r) do
          if placement(i) == Wide then wide += i
          i += 1
      r += 1
    gridBuilt = false

  def findPairs(pairs: PairBuffer): Unit = findPairs(pairs, inGridOrder = true)

  /** `findPairs`, with the pairs in SiMS's coarse grid order or (`inGridOrder` false, for
    * a solver that does not need it) in the internal grid's own order, still deterministic:
    * each shape's partners in the order its cells find them.
    */
  def findPairs(pairs: PairBuffer, inGridOrder: Boolean): Unit =
    sorted = inGridOrder
    pairs.clear(shapes)
    resetGrid()
    val side = _gridSide
    var i = 0
    while sorted && i < count do
      coarseX0(i) = cell(boxMinX(i), side)
      coarseY0(i) = cell(boxMinY(i), side)
      i += 1
    i = 0
    while i < count do
      val p = placement(i)
      if p == Fine || p == Wide then
        groupSize = 0
        if sorted then
          groupX0 = coarseX0(i)
          groupY0 = coarseY0(i)
          groupRows = cell(boxMaxY(i), side) - groupY0 + 1
        if p == Wide then
          // Too big for the fine grid: tested against every earlier grid shape instead.
          var j = 0
          while j < i do
            val q = placement(j)
            if (q == Fine || q == Wide) && candidates(j, i) then partner(j, i, pairs)
            j += 1
        else
          val x0 = fineX0(i); val y0 = fineY0(i)
          forEachFineCell(i) { (cx, cy) =>
            val slot = grid.open(cx, cy)
            var entry = grid.head(slot)
            while entry >= 0 do
              val j = grid.shapeOf(entry)
              // Each pair once: in the fine cell holding the corner of the bounds' overlap.
              if math.max(fineX0(j), x0) == cx && math.max(fineY0(j), y0) == cy && candidates(j, i) then
                partner(j, i, pairs)
              entry = grid.nextEntry(entry)
            grid.push(slot, i)
          }
          var k = 0
          while k < wide.length && wide(k) < i do
            val j = wide(k)
            if candidates(j, i) then partner(j, i, pairs)
            k += 1
        var g = 0
        while g < groupSize do
          pairs.add(groupShape(groupKeys(g)), i)
          g += 1
      i += 1
    gridBuilt = true
    largePairs(pairs)

  // Large shapes meet every collidable shape directly: each large shape, its partners by index
  // (every other shape but the large ones before it, whose turn found the pair). The partners
  // come from the fine cells under the large shape's bounds when there are fewer such cells than
  // shapes (a floor under a row of boxes), else from all shapes; the same partners either way.
  private def largePairs(pairs: PairBuffer): Unit =
    largeFrom = pairs.size
    var k = 0
    while k < large.length do
      val big = large(k)
      val partners = if fineMinX <= fineMaxX then partnersInCells(big) else -1
      if partners < 0 then
        var j = 0
        while j < count do
          val earlierLarge = j < big && placement(j) == Large
          if j != big && placement(j) != Ignored && !earlierLarge && candidates(j, big) then
            if j < big then pairs.add(j, big) else pairs.add(big, j)
          j += 1
      else
        var n = 0
        while n < partners do
          val j = found(n)
          if candidates(j, big) then
            if j < big then pairs.add(j, big) else pairs.add(big, j)
          n += 1
      k += 1

  /** Puts into `found`, in index order, the shapes that may meet the large shape `big`: the fine
    * shapes in the fine cells under its bounds (each once, in the cell holding the corner of the
    * two boxes of cells' overlap), the wide ones and the large ones after it; returns how many,
    * or -1 when its bounds cover more fine cells than there are shapes (then all are checked).
    */
  private def partnersInCells(big: Int): Int =
    val x0 = math.max(0, fineCell(boxMinX(big) - originX, perFine))
    val y0 = math.max(0, fineCell(boxMinY(big) - originY, perFine))
    val x1 = math.min(fineCell(fineMaxX - originX, perFine), fineCell(boxMaxX(big) - originX, perFine))
    val y1 = math.min(fineCell(fineMaxY - originY, perFine), fineCell(boxMaxY(big) - originY, perFine))
    if x0 <= x1 && y0 <= y1 && cellCount(x0, x1, y0, y1) > count then -1
    else
      var n = 0
      if found.length < count then found = new Array[Int](math.max(count, 2 * found.length))
      forEachEntry(x0, x1, y0, y1) { (j, cx, cy) =>
        if math.max(fineX0(j), x0) == cx && math.max(fineY0(j), y0) == cy then
          found(n) = j
          n += 1
      }
      var w = 0
      while w < wide.length do
        found(n) = wide(w)
        n += 1
        w += 1
      var l = 0
      while l < large.length do
        if large(l) > big then
          found(n) = large(l)
          n += 1
        l += 1
      java.util.Arrays.sort(found, 0, n)
      n

  /** Number of shapes of the last `update`. */
  def shapeCount: Int = count

  /** Starts `findPairs(pairs, inGridOrder = false)` shared among threads (after `endFineCells`):
    * every fine shape goes into the fine grid, after which `findPairsOf` may run for ranges of
    * shapes on several threads, each into a buffer of its own, and `endShared` puts the buffers
    * into `pairs`: the same pairs in the same order. Returns false when it filled the grid itself
    * (a sparse grid, or one range); true when the grid is to be filled by `buildGridOf` for each
    * range of the last `beginFineCells` (at once), then `linkGridOf` for ranges of its
    * `gridCells` cells (at once), then `endSharedGrid`: the grid one thread fills.
    */
  def beginSharedGrid(pairs: PairBuffer): Boolean =
    sorted = false
    pairs.clear(shapes)
    resetGrid()
    if !grid.isDense || fineRanges < 2 then
      fillGrid()
      false
    else
      // Each range's entries follow the earlier ranges'.
      var first = 0
      var r = 0
      while r < fineRanges do
        val n = rangeEntries(r)
        rangeEntries(r) = first
        first += n
        r += 1
      grid.beginRanges(fineRanges, first)
      true

  /** Puts range `range`'s fine shapes into its own chains of the fine grid (see `beginSharedGrid`). */
  def buildGridOf(range: Int): Unit =
    var entry = rangeEntries(range)
    var i = rangeFrom(range)
    while i < rangeUntil(range) do
      if placement(i) == Fine then
        forEachFineCell(i) { (cx, cy) =>
          grid.insertInRange(range, cx, cy, i, entry)
          entry += 1
        }
      i += 1

  /** The cells of the fine grid under construction (see `beginSharedGrid`). */
  def gridCells: Int = grid.cells

  /** Joins the ranges' chains of cells `from` until `until` (see `beginSharedGrid`). */
  def linkGridOf(from: Int, until: Int): Unit = grid.linkRanges(from, until)

  /** Ends a grid built by several threads (see `beginSharedGrid`). */
  def endSharedGrid(): Unit = gridBuilt = true

  /** The pairs of shapes `from` until `until` (a shape's partners among the earlier shapes, as
    * `findPairs` finds them) into `out`, which is cleared first. Reads the grid only: ranges
    * may run at once. Returns the pair tests made (see `pairTests`).
    */
  def findPairsOf(from: Int, until: Int, out: PairBuffer): Long =
    out.clear(shapes)
    var tests = 0L
    var i = from
    while i < until do
      val p = placement(i)
      if p == Wide then
        var j = 0
        while j < i do
          val q = placement(j)
          if q == Fine || q == Wide then
            tests += 1
            if overlapAccepted(j, i) then out.add(j, i)
          j += 1
      else if p == Fine then
        val x0 = fineX0(i); val y0 = fineY0(i)
        forEachFineCell(i) { (cx, cy) =>
          // The cell holds every shape, the latest first: the earlier ones follow shape i.
          var entry = grid.firstEntry(cx, cy)
          while grid.shapeOf(entry) != i do entry = grid.nextEntry(entry)
          entry = grid.nextEntry(entry)
          while entry >= 0 do
            val j = grid.shapeOf(entry)
            if math.max(fineX0(j), x0) == cx && math.max(fineY0(j), y0) == cy then
              tests += 1
              if overlapAccepted(j, i) then out.add(j, i)
            entry = grid.nextEntry(entry)
        }
        var k = 0
        while k < wide.length && wide(k) < i do
          val j = wide(k)
          tests += 1
          if overlapAccepted(j, i) then out.add(j, i)
          k += 1
      i += 1
    tests

  /** Ends a shared `findPairs`: appends the first `count` of `ranges` (in order) to `pairs`, then
    * the large shapes' pairs; counts the ranges' pair `tests`.
    */
  def endShared(pairs: PairBuffer, ranges: Array[PairBuffer], count: Int, tests: Long): Unit =
    var r = 0
    while r < count do
      pairs.append(ranges(r))
      r += 1
    pairTests += tests
    largePairs(pairs)

  def query(minX: Double, minY: Double, maxX: Double, maxY: Double, found: ArrayBuffer[Shape]): Unit =
    if !gridBuilt then buildGrid()
    queryStamp += 1
    foundIndices.clear()
    val x0 = fineCell(minX - originX, perFine); val x1 = fineCell(maxX - originX, perFine)
    val y0 = fineCell(minY - originY, perFine); val y1 = fineCell(maxY - originY, perFine)
    if cellCount(x0, x1, y0, y1) > QueryCellLimit then
      // A box over many cells: every shape's bounds are checked, which is cheaper.
      var i = 0
      while i < count do
        if placement(i) != Ignored then consider(i, minX, minY, maxX, maxY)
        i += 1
    else
      forEachEntry(x0, x1, y0, y1)((i, _, _) => consider(i, minX, minY, maxX, maxY))
      var k = 0
      while k < wide.length do { consider(wide(k), minX, minY, maxX, maxY); k += 1 }
      k = 0
      while k < large.length do { consider(large(k), minX, minY, maxX, maxY); k += 1 }
    foundIndices.sortInPlace()
    var k = 0
    while k < foundIndices.length do
      found += shapes(foundIndices(k))
      k += 1

  def rayCast(fromX: Double, fromY: Double, toX: Double, toY: Double, visitor: Broadphase.RayVisitor): Unit =
    if !gridBuilt then buildGrid()
    queryStamp += 1
    val dx = toX - fromX
    val dy = toY - fromY
    var limit = 1.0
    // Shapes outside the fine grid first, each once: a ground among them limits the walk.
    var k = 0
    while k < large.length do { limit = offer(large(k), fromX, fromY, dx, dy, limit, visitor); k += 1 }
    k = 0
    while k < wide.length do { limit = offer(wide(k), fromX, fromY, dx, dy, limit, visitor); k += 1 }
    // Then the fine grid's cells along the ray, in order (a digital differential analyser),
    // over the part of the ray inside the box of the grid's shapes.
    val enter = rayEntry(fineMinX, fineMinY, fineMaxX, fineMaxY, fromX, fromY, dx, dy)
    val leave = rayExit(fineMinX, fineMinY, fineMaxX, fineMaxY, fromX, fromY, dx, dy, limit)
    if enter <= leave then
      var cx = fineCell(fromX + enter * dx - originX, perFine)
      var cy = fineCell(fromY + enter * dy - originY, perFine)
      val endX = fineCell(fromX + leave * dx - originX, perFine)
      val endY = fineCell(fromY + leave * dy - originY, perFine)
      val stepX = if endX > cx then 1 else -1
      val stepY = if endY > cy then 1 else -1
      val cellSide = 1 / perFine
      // Fractions of the ray at its next crossings of a vertical and a horizontal cell border,
      // and between two such crossings.
      // (Fine cells count from the grid's origin.)
      var nextX = if dx > 0 then (originX + (cx + 1L) * cellSide - fromX) / dx
      else if dx < 0 then (originX + cx * cellSide - fromX) / dx else Double.PositiveInfinity
      var nextY = if dy > 0 then (originY + (cy + 1L) * cellSide - fromY) / dy
      else if dy < 0 then (originY + cy * cellSide - fromY) / dy else Double.PositiveInfinity
      val deltaX = if dx != 0 then cellSide / math.abs(dx) else Double.PositiveInfinity
      val deltaY = if dy != 0 then cellSide / math.abs(dy) else Double.PositiveInfinity
      // Exactly the cells between the two ends: rounding of the crossings cannot run away.
      var steps = math.abs(endX.toLong - cx) + math.abs(endY.toLong - cy)
      var walking = true
      if steps > math.max(QueryCellLimit, count.toDouble) then
        // More cells than shapes (shapes far apart): every shape's bounds are checked, which is cheaper.
        walking = false
        var i = 0
        while i < count do
          if placement(i) == Fine then limit = offer(i, fromX, fromY, dx, dy, limit, visitor)
          i += 1
      while walking do
        var entry = grid.firstEntry(cx, cy)
        while entry >= 0 do
          limit = offer(grid.shapeOf(entry), fromX, fromY, dx, dy, limit, visitor)
          entry = grid.nextEntry(entry)
        // Shapes crossed before `limit` lie in the cells before it, all walked by now.
        if steps == 0 || math.min(nextX, nextY) > limit then walking = false
        else
          if nextX < nextY && cx != endX || cy == endY then
            cx += stepX
            nextX += deltaX
          else
            cy += stepY
            nextY += deltaY
          steps -= 1

  /** Offers shape i to the visitor once per query, if the ray crosses its bounds before
    * `limit`; returns the visitor's new limit (or the old one).
    */
  private def offer(i: Int, fromX: Double, fromY: Double, dx: Double, dy: Double, limit: Double,
      visitor: Broadphase.RayVisitor): Double =
    if foundStamp(i) == queryStamp then limit
    else
      foundStamp(i) = queryStamp
      val enter = rayEntry(boxMinX(i), boxMinY(i), boxMaxX(i), boxMaxY(i), fromX, fromY, dx, dy)
      val leave = rayExit(boxMinX(i), boxMinY(i), boxMaxX(i), boxMaxY(i), fromX, fromY, dx, dy, limit)
      if enter <= leave then visitor.visit(shapes(i), limit) else limit

  /** Adds shape i to the query's result once, if its bounds overlap the box. */
  private def consider(i: Int, minX: Double, minY: Double, maxX: Double, maxY: Double): Unit =
    if foundStamp(i) != queryStamp &&
      sims.geometry.AABB.overlaps(boxMinX(i), boxMinY(i), boxMaxX(i), boxMaxY(i), minX, minY, maxX, maxY) then
      foundStamp(i) = queryStamp
      foundIndices += i

  /** Puts every fine shape into the fine grid (for a query without a `findPairs` since the
    * last update).
    */
  private def buildGrid(): Unit =
    resetGrid()
    fillGrid()

  // Shape by shape and cell by cell, as `findPairs` pushes them (`findPairsOf` relies on it).
  private def fillGrid(): Unit =
    var i = 0
    while i < count do
      if placement(i) == Fine then
        forEachFineCell(i)((cx, cy) => grid.insert(cx, cy, i))
      i += 1
    gridBuilt = true

  /** Empties the fine grid for this update's shapes: the box of their fine cells counts from
    * (0, 0), the cell of the lower-left corner of their bounds, to the cell of the upper-right
    * corner of `fineMinX` ... `fineMaxY`.
    */
  private def resetGrid(): Unit =
    if fineMinX <= fineMaxX then
      val columns = fineCell(fineMaxX - originX, perFine)
      val rows = fineCell(fineMaxY - originY, perFine)
      if columns < Int.MaxValue && rows < Int.MaxValue then grid.reset(count, columns + 1, rows + 1)
      else grid.reset(count)
    else grid.reset(count)

  /** How many pairs of shapes `findPairs` has tested so far: the work it does (for the tests
    * that the grid stays linear).
    */
  private[sims] var pairTests: Long = 0

  /** Calls `visit(shape, cx, cy)` for each entry of the fine cells (cx, cy) from (x0, y0) to
    * (x1, y1), x, then y (inlined: no closure; Long counters, as in `forEachFineCell`).
    */
  private inline def forEachEntry(x0: Int, x1: Int, y0: Int, y1: Int)(inline visit: (Int, Long, Long) => Unit): Unit =
    var cxLong = x0.toLong
    while cxLong <= x1 do
      var cyLong = y0.toLong
      while cyLong <= y1 do
        var entry = grid.firstEntry(cxLong.toInt, cyLong.toInt)
        while entry >= 0 do
          visit(grid.shapeOf(entry), cxLong, cyLong)
          entry = grid.nextEntry(entry)
        cyLong += 1
      cxLong += 1

  /** Calls `visit` for each fine cell of shape i, x, then y (inlined: no closure). Long counters:
    * a cell index at Int.MaxValue must not wrap around.
    */
  private inline def forEachFineCell(i: Int)(inline visit: (Int, Int) => Unit): Unit =
    var cxLong = fineX0(i).toLong
    while cxLong <= fineX1(i) do
      var cyLong = fineY0(i).toLong
      while cyLong <= fineY1(i) do
        visit(cxLong.toInt, cyLong.toInt)
        cyLong += 1
      cxLong += 1

  /** Shapes j and i may collide: their bounds of this step overlap and the filter accepts them. */
  private def candidates(j: Int, i: Int): Boolean =
    pairTests += 1
    overlapAccepted(j, i)

  private def overlapAccepted(j: Int, i: Int): Boolean =
    overlap(j, i) && (if keeping then keepable(j, i) else accepts(j, i))

  /** Whether the bounds of shapes j and i overlap. */
  private[broadphase] def overlap(j: Int, i: Int): Boolean =
    sims.geometry.AABB.overlaps(boxMinX(j), boxMinY(j), boxMaxX(j), boxMaxY(j),
      boxMinX(i), boxMinY(i), boxMaxX(i), boxMaxY(i))

  /** Whether `KeptPairs` keeps the pair of shapes j and i: the filter's answer for two plain
    * shapes (it holds while their kinds do), and shapes of different bodies otherwise.
    */
  private def keepable(j: Int, i: Int): Boolean =
    if filterKind(j) != General && filterKind(i) != General then accepts(j, i) else owner(j) ne owner(i)

  /** Whether the filter accepts the kept pair of shapes j and i now (see `keepable`). */
  private[broadphase] def acceptsKept(j: Int, i: Int): Boolean =
    (filterKind(j) != General && filterKind(i) != General) || PairFilter.accepts(shapes(j), shapes(i))

  /** Whether shape i is left out of this update (not collidable, or a sensor). */
  private[broadphase] def ignored(i: Int): Boolean = placement(i) == Ignored

  /** Shape i's kind for the filter in this update (see `kindOf`). */
  private[broadphase] def kind(i: Int): Byte = filterKind(i)

  /** Shape i's body, from this update. */
  private[broadphase] def body(i: Int): Body = owner(i)

  /** The shapes of the last update. */
  private[broadphase] def shapeArray: Array[Shape] = shapes

  /** Builds the fine grid from this update's bounds, after `endUpdate` (for `partnersOf`). */
  private[broadphase] def fillFineGrid(): Unit = buildGrid()

  /** Adds to `out` the candidate pairs of shape e with every other shape of this update, the
    * earlier shape first, but for the shapes marked in `marks` before e (whose own call finds
    * those pairs); needs the fine grid (`fillFineGrid`).
    */
  private[broadphase] def partnersOf(e: Int, marks: Array[Boolean], out: PairBuffer): Unit =
    val p = placement(e)
    if p == Fine then
      val x0 = fineX0(e); val y0 = fineY0(e)
      forEachFineCell(e) { (cx, cy) =>
        var entry = grid.firstEntry(cx, cy)
        while entry >= 0 do
          val j = grid.shapeOf(entry)
          // Each pair once: in the fine cell holding the corner of the bounds' overlap.
          if j != e && !(j < e && marks(j)) && math.max(fineX0(j), x0) == cx && math.max(fineY0(j), y0) == cy then
            partnerOf(e, j, out)
          entry = grid.nextEntry(entry)
      }
      var k = 0
      while k < wide.length do
        val j = wide(k)
        if !(j < e && marks(j)) then partnerOf(e, j, out)
        k += 1
      k = 0
      while k < large.length do
        val j = large(k)
        if !(j < e && marks(j)) then partnerOf(e, j, out)
        k += 1
    else if p != Ignored then
      var j = 0
      while j < count do
        if j != e && placement(j) != Ignored && !(j < e && marks(j)) then partnerOf(e, j, out)
        j += 1

  private def partnerOf(e: Int, j: Int, out: PairBuffer): Unit =
    pairTests += 1
    if overlapAccepted(j, e) then
      if j < e then out.add(j, e) else out.add(e, j)

  /** Marks the fine grid as not built from this update's bounds (the pairs came from elsewhere). */
  private[broadphase] def gridUnused(): Unit = gridBuilt = false

  /** [[PairFilter.accepts]] for shapes j and i: for two plain shapes, different bodies not both
    * immovable, which is what the filter's rules come to for them.
    */
  private def accepts(j: Int, i: Int): Boolean =
    val a = filterKind(j)
    val b = filterKind(i)
    if a != General && b != General then (owner(j) ne owner(i)) && !(a == PlainImmovable && b == PlainImmovable)
    else PairFilter.accepts(shapes(j), shapes(i))

  /** Partner j of shape i, found: unsorted, straight into `pairs` (the order found); sorted,
    * into the group, which `findPairs` puts into `pairs` once shape i's cells are done.
    */
  private inline def partner(j: Int, i: Int, pairs: PairBuffer): Unit =
    if sorted then addToGroup(j, i) else pairs.add(j, i)

  /** Inserts partner j of shape i into the group, in the coarse grid's order: by the rank of the
    * coarse cell holding the overlap's corner among i's cells, then the later shape first.
    */
  private def addToGroup(j: Int, i: Int): Unit =
    if groupSize == groupKeys.length then groupKeys = java.util.Arrays.copyOf(groupKeys, 2 * groupSize)
    val cx = math.max(coarseX0(j), coarseX0(i))
    val cy = math.max(coarseY0(j), coarseY0(i))
    val rank = (cx - groupX0) * groupRows + (cy - groupY0)
    val key = (rank << 32) | (Int.MaxValue - j).toLong
    var g = groupSize
    while g > 0 && groupKeys(g - 1) > key do
      groupKeys(g) = groupKeys(g - 1)
      g -= 1
    groupKeys(g) = key
    groupSize += 1

  private inline def boxMinX(i: Int): Double = boxes(4 * i)
  private inline def boxMinY(i: Int): Double = boxes(4 * i + 1)
  private inline def boxMaxX(i: Int): Double = boxes(4 * i + 2)
  private inline def boxMaxY(i: Int): Double = boxes(4 * i + 3)
  private inline def fineX0(i: Int): Int = fines(4 * i)
  private inline def fineY0(i: Int): Int = fines(4 * i + 1)
  private inline def fineX1(i: Int): Int = fines(4 * i + 2)
  private inline def fineY1(i: Int): Int = fines(4 * i + 3)

  private def ensureCapacity(n: Int): Unit =
    if placement.length < n then
      val capacity = math.max(n, 2 * placement.length)
      boxes = new Array[Double](4 * capacity)
      placement = new Array[Byte](capacity)
      owner = new Array[Body](capacity); filterKind = new Array[Byte](capacity)
      coarseX0 = new Array[Long](capacity); coarseY0 = new Array[Long](capacity)
      fines = new Array[Int](4 * capacity)
      foundStamp = new Array[Int](capacity)
      queryStamp = 0

private[sims] object UniformGrid:
  /** Side of the internal fine grid's cells per mean extent of the shapes in it. */
  private val FineCellPerExtent = 1.5
  /** Shapes covering more fine cells than this are tested against all earlier shapes. */
  private val FineShapeCells = 64.0
  /** A query box covering more fine cells than this, or a ray crossing more than this and more
    * than there are shapes, checks every shape's bounds instead.
    */
  private val QueryCellLimit = 4096.0
  private val Fine: Byte = 0
  private val Wide: Byte = 1
  private val Large: Byte = 2
  private val Ignored: Byte = 3

  // A shape's kind for the filter (see `kindOf`).
  private val General: Byte = 0
  private val PlainMovable: Byte = 1
  private val PlainImmovable: Byte = 2

  /** Plain (movable or immovable) when the filter accepts the shape with any other plain shape
    * of another body, not both immovable: collidable, not a sensor, the default category, mask
    * and group, no transient shapes and no joint that keeps its body from colliding; otherwise
    * General, and the filter itself decides.
    */
  private def kindOf(s: Shape): Byte =
    if s.collidable && !s.sensor && s.groupIndex == Defaults.GroupIndex && s.categoryBits == Defaults.CategoryBits &&
      s.maskBits == Defaults.MaskBits && s.transientShapes.isEmpty && (s.body.jointPartners eq Nil)
    then if s.body.immovable then PlainImmovable else PlainMovable
    else General

  /** Number of cells from (x0, y0) to (x1, y1), inclusive, as a Double: with cell indices
    * clamped to the Int range a Long product overflows (2^32 squared) and a huge shape would
    * count as small.
    */
  private inline def cellCount(x0: Int, x1: Int, y0: Int, y1: Int): Double = (x1.toDouble - x0 + 1) * (y1.toDouble - y0 + 1)

  /** The shape index in a group key. */
  private inline def groupShape(key: Long): Int = Int.MaxValue - (key & 0xffffffffL).toInt

  /** The fraction at which the ray from (x, y) along (dx, dy) enters the box, at least 0; more
    * than its `rayExit` when it misses the box before the exit's limit (slabs: the later of the
    * two axes' entries, the earlier of their exits).
    */
  private def rayEntry(minX: Double, minY: Double, maxX: Double, maxY: Double, x: Double, y: Double, dx: Double,
      dy: Double): Double =
    math.max(0.0, math.max(slabEntry(minX, maxX, x, dx), slabEntry(minY, maxY, y, dy)))

  /** The fraction at which the ray leaves the box, at most `limit` (see `rayEntry`). */
  private def rayExit(minX: Double, minY: Double, maxX: Double, maxY: Double, x: Double, y: Double, dx: Double,
      dy: Double, limit: Double): Double =
    math.min(limit, math.min(slabExit(minX, maxX, x, dx), slabExit(minY, maxY, y, dy)))

  /** Where the line p + t d enters the slab [min, max] of one axis (-infinity if it starts in it
    * and runs along it, +infinity if it runs along it outside).
    */
  private inline def slabEntry(min: Double, max: Double, p: Double, d: Double): Double =
    if d > 0 then (min - p) / d
    else if d < 0 then (max - p) / d
    else if p >= min && p <= max then Double.NegativeInfinity else Double.PositiveInfinity

  /** Where the line leaves the slab (see `slabEntry`). */
  private inline def slabExit(min: Double, max: Double, p: Double, d: Double): Double =
    if d > 0 then (max - p) / d
    else if d < 0 then (min - p) / d
    else if p >= min && p <= max then Double.PositiveInfinity else Double.NegativeInfinity

  /** Grid cell index of a coordinate: floor(coordinate / side) (clamped to the Long range). */
  private[sims] inline def cell(coordinate: Double, side: Double): Long = math.floor(coordinate / side).toLong

  /** `cell(coordinate, side).toDouble`, without the Long: floor(coordinate / side) clamped to
    * the Long range, NaN to 0.
    */
  private inline def cellIndex(coordinate: Double, side: Double): Double =
    val c = math.floor(coordinate / side)
    if c != c then 0.0 else if c < LongLimit then (if c > -LongLimit then c else -LongLimit) else LongLimit

  /** 2^63: Long.MaxValue as a Double, and minus Long.MinValue. */
  private val LongLimit = 9.223372036854775807e18

  /** Cell of the internal fine grid: floor(coordinate * perSide), clamped to the Int range. */
  private inline def fineCell(coordinate: Double, perSide: Double): Int =
    val c = math.floor(coordinate * perSide)
    if c < Int.MinValue then Int.MinValue else if c > Int.MaxValue then Int.MaxValue else c.toInt
