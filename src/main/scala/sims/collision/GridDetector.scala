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

  /** Looks up the narrowphase methods of every pair once, for all the reruns of this step. */
  private def resolvePairs(): Unit =
    var i = 0
    while i < pairs.size do
      val slot = pairs.slot(i)
      slot.methods = methods.resolve(slot.first, slot.second)
      i += 1

  /** Broadphase: fills `pairs` with every candidate pair once. */
  private def findPairs(): Unit =
    pairs.clear()
    val shapes = world.shapeBuffer
    grid.reset(shapes.length)
    val large = largeShapes
    large.clear()
    val side = _gridSide
    var i = 0
    while i < shapes.length do
      val s = shapes(i)
      if s.collidable then
        val x0 = GridDetector.cell(s.minX, side); val x1 = GridDetector.cell(s.maxX, side)
        val y0 = GridDetector.cell(s.minY, side); val y1 = GridDetector.cell(s.maxY, side)
        if (x1.toLong - x0 + 1) * (y1.toLong - y0 + 1) > GridDetector.LargeShapeCells then large += s
        else
          // Long counters: a cell index at Int.MaxValue must not wrap around.
          var cxLong = x0.toLong
          while cxLong <= x1 do
            val cx = cxLong.toInt
            var cyLong = y0.toLong
            while cyLong <= y1 do
              val cy = cyLong.toInt
              // Pair s with the earlier shapes of this cell, then join the cell.
              var entry = grid.firstEntry(cx, cy)
              while entry >= 0 do
                val other = shapes(grid.shapeOf(entry))
                if firstSharedCell(other, s, cx, cy, side) && GridDetector.candidates(other, s) then
                  pairs.add(other, s)
                entry = grid.nextEntry(entry)
              grid.insert(cx, cy, i)
              cyLong += 1
            cxLong += 1
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

  /** True if (cx, cy) holds the lower-left corner of the two AABBs' overlap: the one cell in
    * which the pair is reported, however many cells the shapes share.
    */
  private def firstSharedCell(a: Shape, b: Shape, cx: Int, cy: Int, side: Double): Boolean =
    GridDetector.cell(math.max(a.minX, b.minX), side) == cx &&
      GridDetector.cell(math.max(a.minY, b.minY), side) == cy

/** Defaults and the built-in narrowphase of [[GridDetector]]. */
object GridDetector:
  /** Default side of a grid cell, m. */
  val DefaultGridSide: Double = 2

  /** Shapes covering more cells than this bypass the grid. */
  val LargeShapeCells: Long = 64

  /** Grid cell index of a coordinate: floor(coordinate / side), clamped to the Int range. */
  private[collision] def cell(coordinate: Double, side: Double): Int =
    val c = math.floor(coordinate / side)
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
