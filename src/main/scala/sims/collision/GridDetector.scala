package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.{Circle, Shape, World}
import sims.geometry.ConvexPolygon

/** The default detector (documentation 5.3): a uniform-grid broadphase followed by a
  * narrowphase of partial functions that users can extend.
  *
  * Broadphase: each shape goes into every square cell of side `gridSide` its AABB touches
  * (cell = floor(coordinate / gridSide)); two shapes are a candidate pair when they share a
  * cell, belong to different bodies that are not both fixed, are both collidable, are not
  * transient to each other and their AABBs overlap. Each unordered pair is reported once,
  * the shape that joined the world first being the pair's first shape. Shapes covering more
  * than [[GridDetector.LargeShapeCells]] cells are kept out of the grid and tested against
  * every shape directly, so one huge ground box does not fill thousands of cells.
  *
  * Narrowphase: `detectionMethods` are tried in order on (first, second) and the first
  * defined one decides; if it says true, the first defined `collisionMethods` entry makes the
  * collision. The choice is resolved once per pair of shape classes and cached (so a method
  * must be defined or not by the shapes' classes alone, as all pattern matches on types are).
  */
class GridDetector(val world: World) extends Detector:
  private var _gridSide = GridDetector.DefaultGridSide

  /** Side of a grid cell in m (default 2). */
  def gridSide: Double = _gridSide

  /** Sets the cell side; must be positive and finite. */
  def gridSide_=(side: Double): Unit = _gridSide = Shape.requirePositive("gridSide", side)

  /** Collision tests, tried in order; append methods for new shape types. */
  val detectionMethods: ArrayBuffer[PartialFunction[(Shape, Shape), Boolean]] = ArrayBuffer(
    GridDetector.BuiltIn.circleCircleTest,
    GridDetector.BuiltIn.polygonPolygonTest,
    GridDetector.BuiltIn.polygonCircleTest,
    GridDetector.BuiltIn.circlePolygonTest)

  /** Collision constructors, tried in order; append methods for new shape types. */
  val collisionMethods: ArrayBuffer[PartialFunction[(Shape, Shape), Collision]] = ArrayBuffer(
    GridDetector.BuiltIn.circleCircleCollision,
    GridDetector.BuiltIn.polygonPolygonCollision,
    GridDetector.BuiltIn.polygonCircleCollision,
    GridDetector.BuiltIn.circlePolygonCollision)

  private val pairs = PairBuffer()
  private val found = ArrayBuffer.empty[Collision]
  private val largeShapes = ArrayBuffer.empty[Shape]
  private val grid = CellGrid()
  private val methods = NarrowphaseCache()

  def collisions: collection.IndexedSeq[Collision] = found

  /** The candidate pairs of the last `detect()`: (first, second) shapes, in order. */
  def candidatePairs: IndexedSeq[(Shape, Shape)] =
    IndexedSeq.tabulate(pairs.size)(i => (pairs.first(i), pairs.second(i)))

  def detect(): Unit =
    findPairs()
    methods.update(detectionMethods, collisionMethods)
    resolvePairs()
    refresh()

  /** Reruns the narrowphase on the pairs of the last `detect()` from the current positions. */
  override def refresh(): Unit =
    if methods.update(detectionMethods, collisionMethods) then resolvePairs()
    found.clear()
    var i = 0
    while i < pairs.size do
      val c = methods.collide(pairs.slot(i))
      if c != null then found += c
      i += 1

  /** Looks up the narrowphase methods of every pair once, for all the reruns of this step, and
    * lets every slot give back the collision objects its pair does not use.
    */
  private def resolvePairs(): Unit =
    var i = 0
    while i < pairs.created do
      val slot = pairs.slot(i)
      if i < pairs.size then
        slot.methods = methods.resolve(slot.first, slot.second)
        methods.releaseUnused(slot, slot.methods.kind)
      else methods.releaseUnused(slot, -1)
      i += 1

  // Broadphase state, reused from step to step: each shape's AABB, read once per step.
  private var boxMinX, boxMinY, boxMaxX, boxMaxY = new Array[Double](0)
  /** Per shape: 0 in the fine grid, 1 tested against all earlier shapes, 2 large, 3 not collidable. */
  private var placement = new Array[Byte](0)
  // Per shape: the coarse and fine cells of its AABB's lower-left corner. Cell functions are
  // monotonic, so the cell of the corner of two AABBs' overlap, cell(max(a, b)), is
  // max(cell(a), cell(b)): computed once per shape instead of once per candidate.
  private var coarseX0, coarseY0, fineX0, fineY0 = new Array[Int](0)
  private val wide = ArrayBuffer.empty[Int]
  // Candidates of the shape being placed: their order keys and shape indices.
  private var groupKeys = new Array[Long](16)
  private var groupSize = 0
  // The coarse cells of the shape being placed: first column and row, number of rows.
  private var groupX0, groupY0 = 0
  private var groupRows = 0L

  /** Broadphase: fills `pairs` with every candidate pair once.
    *
    * The pairs and their order are those of the `gridSide` grid: for each shape in world order,
    * its partners among the earlier shapes, cell by cell of the shape's cells (x, then y), and
    * within a cell the most recently added partner first (a pair is reported in the cell that
    * holds the lower-left corner of the two AABBs' overlap). Coarse cells are crowded with
    * small shapes, so the partners are found with a finer internal grid sized to the shapes
    * and then put in that order: faster, and the same pairs in the same order.
    */
  private def findPairs(): Unit =
    pairs.clear()
    val shapes = world.shapeBuffer
    val n = shapes.length
    if boxMinX.length < n then
      val capacity = math.max(n, 2 * boxMinX.length)
      boxMinX = new Array[Double](capacity); boxMinY = new Array[Double](capacity)
      boxMaxX = new Array[Double](capacity); boxMaxY = new Array[Double](capacity)
      placement = new Array[Byte](capacity)
      coarseX0 = new Array[Int](capacity); coarseY0 = new Array[Int](capacity)
      fineX0 = new Array[Int](capacity); fineY0 = new Array[Int](capacity)
    val side = _gridSide
    val large = largeShapes
    large.clear()
    wide.clear()
    // Bounds, the large shapes, and the mean extent of the others for the fine grid's cells.
    var extentSum = 0.0
    var counted = 0
    var i = 0
    while i < n do
      val s = shapes(i)
      if !s.collidable then placement(i) = GridDetector.Ignored
      else
        val x0 = s.minX; val y0 = s.minY; val x1 = s.maxX; val y1 = s.maxY
        boxMinX(i) = x0; boxMinY(i) = y0; boxMaxX(i) = x1; boxMaxY(i) = y1
        coarseX0(i) = GridDetector.cell(x0, side)
        coarseY0(i) = GridDetector.cell(y0, side)
        val cells = (GridDetector.cell(x1, side).toLong - coarseX0(i) + 1) *
          (GridDetector.cell(y1, side).toLong - coarseY0(i) + 1)
        if cells > GridDetector.LargeShapeCells then
          placement(i) = GridDetector.Large
          large += s
        else
          placement(i) = GridDetector.Fine
          extentSum += math.max(x1 - x0, y1 - y0)
          counted += 1
      i += 1
    val fine =
      val mean = if counted == 0 then side else extentSum / counted * GridDetector.FineCellPerExtent
      if mean > 0 && mean <= side then mean else side
    // Fine cells by multiplication: any consistent cell function serves the internal grid.
    val perFine = 1 / fine
    grid.reset(n)
    i = 0
    while i < n do
      if placement(i) == GridDetector.Fine then
        val x0 = GridDetector.fineCell(boxMinX(i), perFine); val x1 = GridDetector.fineCell(boxMaxX(i), perFine)
        val y0 = GridDetector.fineCell(boxMinY(i), perFine); val y1 = GridDetector.fineCell(boxMaxY(i), perFine)
        fineX0(i) = x0
        fineY0(i) = y0
        groupSize = 0
        groupX0 = coarseX0(i)
        groupY0 = coarseY0(i)
        groupRows = GridDetector.cell(boxMaxY(i), side).toLong - groupY0 + 1
        if (x1.toLong - x0 + 1) * (y1.toLong - y0 + 1) > GridDetector.FineShapeCells then
          // Too big for the fine grid: tested against every earlier shape instead.
          placement(i) = GridDetector.Wide
          var j = 0
          while j < i do
            val p = placement(j)
            if (p == GridDetector.Fine || p == GridDetector.Wide) && candidates(j, i, shapes) then addToGroup(j, i, side)
            j += 1
          wide += i
        else
          // Long counters: a cell index at Int.MaxValue must not wrap around.
          var cxLong = x0.toLong
          while cxLong <= x1 do
            val cx = cxLong.toInt
            var cyLong = y0.toLong
            while cyLong <= y1 do
              val cy = cyLong.toInt
              var entry = grid.firstEntry(cx, cy)
              while entry >= 0 do
                val j = grid.shapeOf(entry)
                // Each pair once: in the fine cell holding the corner of the AABBs' overlap.
                if math.max(fineX0(j), x0) == cx && math.max(fineY0(j), y0) == cy &&
                    candidates(j, i, shapes) then
                  addToGroup(j, i, side)
                entry = grid.nextEntry(entry)
              grid.insert(cx, cy, i)
              cyLong += 1
            cxLong += 1
          var k = 0
          while k < wide.length do
            val j = wide(k)
            if candidates(j, i, shapes) then addToGroup(j, i, side)
            k += 1
        var g = 0
        while g < groupSize do
          pairs.add(shapes(GridDetector.groupShape(groupKeys(g))), shapes(i))
          g += 1
      i += 1
    // Large shapes meet every collidable shape directly.
    var k = 0
    while k < large.length do
      val big = large(k)
      var j = 0
      while j < shapes.length do
        val s = shapes(j)
        val otherIsEarlierLarge = s.worldIndex < big.worldIndex && large.exists(_ eq s)
        if (s ne big) && s.collidable && !otherIsEarlierLarge && GridDetector.candidates(big, s) then
          if s.worldIndex < big.worldIndex then pairs.add(s, big) else pairs.add(big, s)
        j += 1
      k += 1

  /** The pair filters of the broadphase for shapes j and i, from the bounds read this step. */
  private def candidates(j: Int, i: Int, shapes: Array[sims.dynamics.Shape]): Boolean =
    sims.geometry.AABB.overlaps(boxMinX(j), boxMinY(j), boxMaxX(j), boxMaxY(j),
      boxMinX(i), boxMinY(i), boxMaxX(i), boxMaxY(i)) && {
      val a = shapes(j)
      val b = shapes(i)
      (a.body ne b.body) && !(a.body.fixed && b.body.fixed) &&
        (a.transientShapes.isEmpty || !a.transientShapes.contains(b)) &&
        (b.transientShapes.isEmpty || !b.transientShapes.contains(a))
    }

  /** Inserts partner j of shape i into the group, in the coarse grid's order: by the rank of
    * the coarse cell holding the overlap's corner among i's cells, then the later shape first.
    */
  private def addToGroup(j: Int, i: Int, side: Double): Unit =
    val cx = math.max(coarseX0(j), coarseX0(i))
    val cy = math.max(coarseY0(j), coarseY0(i))
    val rank = (cx.toLong - groupX0) * groupRows + (cy.toLong - groupY0)
    val key = (rank << 32) | (Int.MaxValue - j).toLong
    if groupSize == groupKeys.length then groupKeys = java.util.Arrays.copyOf(groupKeys, 2 * groupSize)
    var g = groupSize
    while g > 0 && groupKeys(g - 1) > key do
      groupKeys(g) = groupKeys(g - 1)
      g -= 1
    groupKeys(g) = key
    groupSize += 1

/** Defaults and the built-in narrowphase of [[GridDetector]]. */
object GridDetector:
  /** Default side of a grid cell, m. */
  val DefaultGridSide: Double = 2

  /** Shapes covering more cells than this bypass the grid. */
  val LargeShapeCells: Long = 64

  /** Side of the internal fine grid's cells per mean extent of the shapes in it. */
  private val FineCellPerExtent = 1.5
  /** Shapes covering more fine cells than this are tested against all earlier shapes. */
  private val FineShapeCells = 64L
  private val Fine: Byte = 0
  private val Wide: Byte = 1
  private val Large: Byte = 2
  private val Ignored: Byte = 3

  /** The shape index in a group key. */
  private inline def groupShape(key: Long): Int = Int.MaxValue - (key & 0xffffffffL).toInt

  /** Grid cell index of a coordinate: floor(coordinate / side), clamped to the Int range. */
  private[collision] def cell(coordinate: Double, side: Double): Int =
    val c = math.floor(coordinate / side)
    if c < Int.MinValue then Int.MinValue else if c > Int.MaxValue then Int.MaxValue else c.toInt

  /** Cell of the internal fine grid: floor(coordinate * perSide), clamped to the Int range. */
  private inline def fineCell(coordinate: Double, perSide: Double): Int =
    val c = math.floor(coordinate * perSide)
    if c < Int.MinValue then Int.MinValue else if c > Int.MaxValue then Int.MaxValue else c.toInt

  /** The pair filters of the broadphase (apart from sharing a cell). */
  private[collision] def candidates(a: Shape, b: Shape): Boolean =
    (a.body ne b.body) && a.collidable && b.collidable &&
      !(a.body.fixed && b.body.fixed) &&
      sims.geometry.AABB.overlaps(a.minX, a.minY, a.maxX, a.maxY, b.minX, b.minY, b.maxX, b.maxY) &&
      (a.transientShapes.isEmpty || !a.transientShapes.contains(b)) &&
      (b.transientShapes.isEmpty || !b.transientShapes.contains(a))

  /** The built-in methods: partial functions for users to see and reorder, plus direct calls
    * that skip building a tuple on the hot path.
    */
  private[collision] object BuiltIn:
    /** A built-in test with a direct two-argument entry. */
    final class Test(classes: (Class[?], Class[?]), val kind: Int, val direct: (Shape, Shape) => Boolean)
        extends PartialFunction[(Shape, Shape), Boolean]:
      def isDefinedAt(pair: (Shape, Shape)): Boolean = BuiltIn.matches(classes, pair)
      def apply(pair: (Shape, Shape)): Boolean = direct(pair._1, pair._2)

    /** A built-in collision constructor with a direct two-argument entry. */
    final class Make(classes: (Class[?], Class[?]), val kind: Int, val direct: (Shape, Shape) => Collision)
        extends PartialFunction[(Shape, Shape), Collision]:
      def isDefinedAt(pair: (Shape, Shape)): Boolean = BuiltIn.matches(classes, pair)
      def apply(pair: (Shape, Shape)): Collision = direct(pair._1, pair._2)

    private def matches(classes: (Class[?], Class[?]), pair: (Shape, Shape)): Boolean =
      classes._1.isInstance(pair._1) && classes._2.isInstance(pair._2)

    private val circle = classOf[Circle]
    private val polygon = classOf[ConvexPolygon]
    private type Polygon = Shape & ConvexPolygon

    val circleCircleTest = Test((circle, circle), NarrowphaseCache.CircleCircle,
      (a, b) => CircleCollision.colliding(a.asInstanceOf[Circle], b.asInstanceOf[Circle]))
    val polygonPolygonTest = Test((polygon, polygon), NarrowphaseCache.PolygonPolygon,
      (a, b) => PolyCollision.colliding(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon]))
    val polygonCircleTest = Test((polygon, circle), NarrowphaseCache.PolygonCircle,
      (a, b) => PolyCircleCollision.colliding(a.asInstanceOf[Polygon], b.asInstanceOf[Circle]))
    val circlePolygonTest = Test((circle, polygon), NarrowphaseCache.CirclePolygon,
      (a, b) => PolyCircleCollision.colliding(b.asInstanceOf[Polygon], a.asInstanceOf[Circle]))

    val circleCircleCollision = Make((circle, circle), NarrowphaseCache.CircleCircle,
      (a, b) => CircleCollision(a.asInstanceOf[Circle], b.asInstanceOf[Circle]))
    val polygonPolygonCollision = Make((polygon, polygon), NarrowphaseCache.PolygonPolygon,
      (a, b) => PolyCollision(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon]))
    val polygonCircleCollision = Make((polygon, circle), NarrowphaseCache.PolygonCircle,
      (a, b) => PolyCircleCollision(a.asInstanceOf[Polygon], b.asInstanceOf[Circle]))
    val circlePolygonCollision = Make((circle, polygon), NarrowphaseCache.CirclePolygon,
      (a, b) => PolyCircleCollision(b.asInstanceOf[Polygon], a.asInstanceOf[Circle]))
