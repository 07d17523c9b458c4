package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, Shape, World}
import sims.geometry.Vector2D

/** The grid broadphase finds exactly the pairs a brute-force all-pairs test finds. */
class BroadphaseSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private def bruteForce(world: World): Seq[(Shape, Shape)] =
    val shapes = world.shapes
    for
      i <- shapes.indices
      j <- i + 1 until shapes.length
      a = shapes(i)
      b = shapes(j)
      if a.AABB.overlaps(b.AABB) && PairFilter.accepts(a, b)
    yield (a, b)

  private val shape: Gen[Shape] = RandomScenes.shape(kinds = 3)
  private def scene(shapes: Seq[Shape], gridSide: Double): World = RandomScenes.scene(shapes, gridSide)

  test("grid pairs equal brute-force pairs, in order, each once") {
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0, 7.0), minSuccessful(40)) { (shapes, side) =>
      val world = scene(shapes, side)
      val detector = world.detector.asInstanceOf[GridDetector]
      detector.detect()
      val found = detector.candidatePairs
      found.map(p => (p._1.worldIndex, p._2.worldIndex)).sorted shouldBe
        bruteForce(world).map(p => (p._1.worldIndex, p._2.worldIndex)).sorted
      found.foreach(p => p._1.worldIndex should be < p._2.worldIndex)
      found.distinct.size shouldBe found.size
    }
  }

  test("grid pairs equal brute-force pairs with the shapes in clusters 1 km apart (a sparse grid)") {
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0), minSuccessful(20)) { (shapes, side) =>
      shapes.zipWithIndex.foreach((s, i) => s.pos = s.pos + Vector2D(1000.0 * (i % 3), -700.0 * (i % 2)))
      val world = scene(shapes, side)
      val detector = world.detector.asInstanceOf[GridDetector]
      detector.detect()
      detector.candidatePairs.map(p => (p._1.worldIndex, p._2.worldIndex)).sorted shouldBe
        bruteForce(world).map(p => (p._1.worldIndex, p._2.worldIndex)).sorted
    }
  }

  /** The pairs of the grid's own order (the soft step's), found by one search or shared out in
    * `ranges` ranges of shapes (their bounds, fine cells, fine grid and search), with the pair
    * tests each made and whether the fine grid was built in ranges.
    */
  private def ownOrderPairs(world: World, side: Double, ranges: Int, maxPairs: Int = 1000000): (Seq[(Int, Int)], Long, Boolean) =
    val pipeline = world.collisionPipeline
    val grid = pipeline.broadphase
    val testsBefore = grid.pairTests
    var inRanges = false
    if ranges == 0 then pipeline.findPairs(world.shapeBuffer, side, maxPairs, "maxPairs", 0, 0, inGridOrder = false)
    else
      pipeline.beginSharedBounds(world.shapeBuffer, side, maxPairs, "maxPairs", 0, 0)
      val n = world.shapeBuffer.length
      def start(items: Int, r: Int) = items * r / ranges
      // Every stage's ranges last to first: each writes its own slots only.
      for r <- (0 until ranges).reverse do grid.boundsOf(start(n, r), start(n, r + 1))
      grid.beginFineCells(ranges)
      for r <- (0 until ranges).reverse do grid.fineCellsOf(r, start(n, r), start(n, r + 1))
      grid.endFineCells()
      inRanges = grid.beginSharedGrid(pipeline.pairs)
      if inRanges then
        for r <- (0 until ranges).reverse do grid.buildGridOf(r)
        val cells = grid.gridCells
        for r <- (0 until ranges).reverse do grid.linkGridOf(start(cells, r), start(cells, r + 1))
        grid.endSharedGrid()
      val buffers = Array.fill(ranges)(PairBuffer())
      buffers.foreach(_.limit = maxPairs)
      val tests = (0 until ranges).map(r => grid.findPairsOf(start(n, r), start(n, r + 1), buffers(r))).sum
      grid.endShared(pipeline.pairs, buffers, ranges, tests)
    val pairs = pipeline.pairs
    ((0 until pairs.size).map(i => (pairs.first(i).worldIndex, pairs.second(i).worldIndex)), grid.pairTests - testsBefore,
      inRanges)

  test("the search shared out in ranges of shapes finds the pairs of one search, in its order, with as many tests") {
    forAll(Gen.listOfN(80, shape), Gen.oneOf(0.5, 2.0, 7.0), Gen.oneOf(1, 2, 3, 7, 40), minSuccessful(40)) {
      (shapes, side, ranges) =>
        val world = scene(shapes, side)
        val (alone, aloneTests, _) = ownOrderPairs(world, side, 0)
        val (shared, sharedTests, inRanges) = ownOrderPairs(world, side, ranges)
        shared shouldBe alone
        sharedTests shouldBe aloneTests
        if ranges == 1 then inRanges shouldBe false
        alone.sorted shouldBe bruteForce(world).map(p => (p._1.worldIndex, p._2.worldIndex)).sorted
    }
  }

  test("the search shared out in ranges finds the pairs of one search in a sparse grid too (clusters 1 km apart)") {
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0), Gen.oneOf(2, 3, 7), minSuccessful(20)) { (shapes, side, ranges) =>
      shapes.zipWithIndex.foreach((s, i) => s.pos = s.pos + Vector2D(1000.0 * (i % 3), -700.0 * (i % 2)))
      val world = scene(shapes, side)
      val (alone, _, _) = ownOrderPairs(world, side, 0)
      val (shared, _, inRanges) = ownOrderPairs(world, side, ranges)
      shared shouldBe alone
      inRanges shouldBe false
    }
  }

  /** A pile: `n` small shapes of the first three kinds within 6 m, a body each (a dense fine grid). */
  private def pile(n: Int): Gen[World] =
    val small =
      for
        size <- Gen.choose(0.05, 0.3)
        kind <- Gen.choose(0, 2)
        x <- Gen.choose(0.0, 6.0)
        y <- Gen.choose(0.0, 6.0)
      yield
        val s = kind match
          case 0 => Circle(size, 1)
          case 1 => Rectangle(size, size / 2, 1)
          case _ => RegularPolygon(5, size, 1)
        s.pos = Vector2D(x, y)
        s
    Gen.listOfN(n, small).map { shapes =>
      val world = World()
      shapes.foreach(s => world += s.asBody)
      world
    }

  test("a pile's fine grid is built in ranges, step after step as its shapes move, with the pairs of one search") {
    // The ranges' chains are stamped per build: a cell of an earlier build must not leak into a later one.
    forAll(pile(150), Gen.oneOf(2, 3, 7), minSuccessful(10)) { (world, ranges) =>
      for round <- 0 until 5 do
        val (alone, aloneTests, _) = ownOrderPairs(world, 2.0, 0)
        val (shared, sharedTests, inRanges) = ownOrderPairs(world, 2.0, ranges)
        inRanges shouldBe true
        shared shouldBe alone
        sharedTests shouldBe aloneTests
        alone.sorted shouldBe bruteForce(world).map(p => (p._1.worldIndex, p._2.worldIndex)).sorted
        for (body, i) <- world.bodies.zipWithIndex do
          body.pos = body.pos + Vector2D(0.3 * ((i + round) % 3 - 1), 0.2 * (i % 2))
    }
  }

  test("a large shape's pairs come last, large shape by large shape, each one's partners in shape order") {
    // Floors 600 m long (far more than 64 cells of the grid: large shapes) at random heights,
    // some far from everything, among random shapes; the grid finds the floors' partners in
    // the fine cells under them, or checks every shape when those cells outnumber the shapes.
    val floorHeight = Gen.oneOf(Gen.choose(-25.0, 25.0), Gen.const(5000.0))
    forAll(Gen.listOfN(60, shape), Gen.listOfN(4, floorHeight), Gen.oneOf(0.5, 2.0), minSuccessful(40)) {
      (shapes, heights, side) =>
        val world = scene(shapes, side)
        for y <- heights do
          val floor = sims.dynamics.Rectangle(300, 0.3, 1)
          floor.pos = Vector2D(0, y)
          world += floor.asBody
        val all = world.shapes
        def cells(low: Double, high: Double) = math.floor(high / side) - math.floor(low / side) + 1
        val large = all.filter(s => cells(s.minX, s.maxX) * cells(s.minY, s.maxY) > 64).map(_.worldIndex).toSet
        val expected =
          for
            big <- large.toSeq.sorted
            other <- all.sortBy(_.worldIndex)
            j = other.worldIndex
            if j != big && !(large(j) && j < big)
            if all(big).AABB.overlaps(other.AABB) && PairFilter.accepts(all(big), other)
          yield (math.min(j, big), math.max(j, big))
        val (found, _, _) = ownOrderPairs(world, side, 0)
        found.filter((a, b) => large(a) || large(b)) shouldBe expected
        found.takeRight(expected.size) shouldBe expected
    }
  }

  test("the search shared out fails past maxPairs as one search does, naming the limit") {
    val world = World()
    for i <- 0 until 40 do
      val ball = Circle(0.5, 1)
      ball.pos = Vector2D(0.01 * i, 0)
      world += ball.asBody
    for ranges <- Seq(0, 3) do
      val error = intercept[IllegalStateException](ownOrderPairs(world, 2.0, ranges, maxPairs = 100))
      error.getMessage should include("more than 100 candidate pairs")
      error.getMessage should include("maxPairs")
  }

  test("pair filters: same body, not collidable, transient, both fixed") {
    val world = World()
    val a = Circle(1, 1)
    val b = Circle(1, 1); b.pos = Vector2D(0.5, 0)
    world += Body(a, b) // same body
    val c = Circle(1, 1); c.pos = Vector2D(0, 0.5); c.collidable = false
    world += c.asBody
    val d = Circle(1, 1); d.pos = Vector2D(0.2, 0.2); d.transientShapes = Set(a, b)
    world += d.asBody
    val e = Circle(1, 1); e.pos = Vector2D(-0.3, 0); e.asBody.fixed = true
    val f = Circle(1, 1); f.pos = Vector2D(-0.3, 0.1); f.asBody.fixed = true
    world += e.body
    world += f.body
    val detector = world.detector.asInstanceOf[GridDetector]
    detector.detect()
    detector.candidatePairs.map((p, q) => (p.worldIndex, q.worldIndex)).toSet shouldBe
      Set((0, 4), (0, 5), (1, 4), (1, 5), (3, 4), (3, 5)) // a, b, d with e, f; never e-f
  }

  test("the same scene gives the same pairs in the same order") {
    def pairs(): Seq[(Int, Int)] =
      val world = World()
      for i <- 0 until 200 do
        val c = Circle(0.3, 1)
        c.pos = Vector2D((i * 37 % 23) * 0.5, (i * 11 % 17) * 0.5)
        world += c.asBody
      world.detector.detect()
      world.detector.asInstanceOf[GridDetector].candidatePairs.map((a, b) => (a.worldIndex, b.worldIndex))
    pairs() shouldBe pairs()
  }

  test("gridSide must be positive") {
    val d = GridDetector(World())
    d.gridSide shouldBe 2.0
    intercept[IllegalArgumentException](d.gridSide = 0).getMessage should include("gridSide")
  }

  test("a box query finds exactly the shapes whose bounds overlap the box, in world order") {
    val box =
      for
        x <- Gen.choose(-25.0, 25.0)
        y <- Gen.choose(-25.0, 25.0)
        w <- Gen.oneOf(Gen.choose(0.0, 1.0), Gen.choose(1.0, 40.0))
        h <- Gen.choose(0.0, 10.0)
      yield sims.geometry.AABB(Vector2D(x, y), Vector2D(x + w, y + h))
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0), Gen.listOfN(5, box), minSuccessful(30)) { (shapes, side, boxes) =>
      val world = scene(shapes, side)
      world.shapes.head.collidable = false // left out of queries too
      val grid = sims.collision.broadphase.UniformGrid()
      grid.gridSide = side
      grid.update(world.shapeBuffer, 0)
      for (query, i) <- boxes.zipWithIndex do
        if i == 2 then grid.findPairs(PairBuffer()) // queries work with or without pairs found
        val found = scala.collection.mutable.ArrayBuffer.empty[Shape]
        grid.query(query.minVertex.x, query.minVertex.y, query.maxVertex.x, query.maxVertex.y, found)
        found.toSeq shouldBe world.shapes.filter(s => s.collidable && s.AABB.overlaps(query))
    }
  }

  test("a ray is offered only the shapes near it, each once, and the walk stops at the limit") {
    val world = World()
    for i <- 0 until 100; j <- 0 until 100 do
      val c = Circle(0.1, 1)
      c.pos = Vector2D(i * 0.3, j * 0.3)
      world += c.asBody
    val grid = sims.collision.broadphase.UniformGrid()
    grid.update(world.shapeBuffer, 0)
    val offered = scala.collection.mutable.ArrayBuffer.empty[Shape]
    def walk(fromX: Double, fromY: Double, toX: Double, toY: Double, stopAt: Double): Unit =
      offered.clear()
      grid.rayCast(fromX, fromY, toX, toY,
        new sims.collision.broadphase.Broadphase.RayVisitor:
          def visit(shape: Shape, limit: Double): Double = { offered += shape; math.min(limit, stopAt) })
    // Along the row y = 0.3 across the whole grid: its 100 balls and none of the other 9,900 far from it.
    walk(-1, 0.3, 31, 0.3, 1)
    offered.size shouldBe offered.distinct.size
    offered.count(s => math.abs(s.pos.y - 0.3) < 1e-9) shouldBe 100
    offered.forall(s => math.abs(s.pos.y - 0.3) < 0.31) shouldBe true
    // A visitor that wants nothing beyond a tenth of the ray stops the walk there.
    walk(-1, 0.3, 31, 0.3, 0.1)
    offered.map(_.pos.x).max should be < 3.3
  }

  test("bounds enlarged by a margin make pairs of shapes that are that close") {
    val world = World()
    val a = Circle(1, 1)
    val b = Circle(1, 1); b.pos = Vector2D(2.05, 0)
    world += a.asBody
    world += b.asBody
    val grid = sims.collision.broadphase.UniformGrid()
    val pairs = PairBuffer()
    grid.update(world.shapeBuffer, 0)
    grid.findPairs(pairs)
    pairs.size shouldBe 0
    grid.update(world.shapeBuffer, 0.03)
    grid.findPairs(pairs)
    pairs.size shouldBe 1
  }
