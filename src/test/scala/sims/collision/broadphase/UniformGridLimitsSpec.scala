package sims.collision.broadphase

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.{GridDetector, PairBuffer, PairFilter}
import sims.dynamics.{Circle, Rectangle, Shape, World}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep}

/** The grid at the edges of what it can represent: huge shapes, scenes far from the
  * origin, and piles of shapes at one point.
  */
class UniformGridLimitsSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  /** A ball of its own body. */
  private def ball(radius: Double, x: Double, y: Double, density: Double = 1): Circle =
    val c = Circle(radius, density)
    c.pos = Vector2D(x, y)
    c.asBody
    c

  /** Balls 0.1 m in radius, 0.25 m apart in a 40 x 40 square whose lower-left ball is at (x, y). */
  private def lattice(x: Double, y: Double): Array[Shape] =
    Array.tabulate[Shape](1600)(k => ball(0.1, x + (k % 40) * 0.25, y + (k / 40) * 0.25))

  private def gridPairs(shapes: Array[Shape]): (Seq[(Int, Int)], Long) =
    val grid = UniformGrid()
    val pairs = PairBuffer()
    grid.update(shapes, 0.06) // bounds enlarged until neighbours overlap
    grid.findPairs(pairs)
    val index = shapes.zipWithIndex.toMap
    ((0 until pairs.size).map(i => (index(pairs.first(i)), index(pairs.second(i)))), grid.pairTests)

  test("a circle of radius 1e150 and a ball: one step under each solver, no OutOfMemoryError, the pair found") {
    for solver <- Seq(ClassicStep, SoftStep()) do
      val world = World()
      world.solver = solver
      world += ball(1e150, 0, 0, density = 1e-300).body // light enough for its inertia to be finite
      world += ball(1, 0, 0).body
      world.gravity = Vector2D.Null
      world.step()
      world.contacts.size shouldBe 1
  }

  test("a fixed ground of 1e10 x 1e10 m goes with the large shapes: a ball comes to rest on it") {
    for solver <- Seq(ClassicStep, SoftStep()) do
      val world = World()
      world.solver = solver
      val ground = Rectangle(1e10, 1e10, 1).asBody
      ground.fixed = true
      world += ground
      val falling = ball(0.5, 0, 1e10 + 1).body
      world += falling
      for _ <- 1 to 120 do world.step()
      falling.pos.y shouldBe (1e10 + 0.5) +- 0.02
  }

  test("huge bounds count as many cells: a shape's cell count cannot overflow to a small number") {
    val grid = UniformGrid()
    val shapes = Array[Shape](ball(3e9, 0, 0), ball(1, 0, 0), ball(1, 1e9, 0))
    grid.update(shapes, 0)
    val pairs = PairBuffer()
    grid.findPairs(pairs)
    pairs.size shouldBe 2
    val found = scala.collection.mutable.ArrayBuffer.empty[Shape]
    grid.query(-1e10, -1e10, 1e10, 1e10, found) // a query over 2^64 clamped cells checks bounds instead
    found.size shouldBe 3
  }

  test("far from the origin the grid stays linear: the same pairs in the same order and the same work at 1e12 m as at 0") {
    val (nearPairs, nearTests) = gridPairs(lattice(0, 0))
    nearPairs.size shouldBe 2 * 40 * 39 + 2 * 39 * 39 // each ball's bounds meet its 8 neighbours'
    for offset <- Seq(1.3e9, 1e12, -1e12) do
      val (farPairs, farTests) = gridPairs(lattice(offset, offset))
      farPairs shouldBe nearPairs
      farTests.toDouble should be <= 1.2 * nearTests
    // without the offset every ball beyond 6e8 m fell into one saturated cell: n^2 / 2 tests
    nearTests should be < 1600L * 40
  }

  test("far from the origin grid pairs equal brute-force pairs") {
    val shape =
      for
        x <- Gen.choose(-5.0, 5.0); y <- Gen.choose(-5.0, 5.0); size <- Gen.choose(0.05, 1.0)
      yield (x, y, size)
    forAll(Gen.listOfN(50, shape), Gen.oneOf(0.0, 2e9, -7e11, 3e14)) { (specs, offset) =>
      val shapes = specs.toArray.map((x, y, size) => ball(size, offset + x, offset + y): Shape)
      val (found, _) = gridPairs(shapes)
      val expected =
        for
          i <- shapes.indices; j <- i + 1 until shapes.length
          a = shapes(i); b = shapes(j)
          if sims.geometry.AABB.overlaps(a.minX - 0.06, a.minY - 0.06, a.maxX + 0.06, a.maxY + 0.06,
            b.minX - 0.06, b.minY - 0.06, b.maxX + 0.06, b.maxY + 0.06) && PairFilter.accepts(a, b)
        yield (i, j)
      found.sorted shouldBe expected
    }
  }

  test("10,000 balls at one point: the step fails at once naming the limit of candidate pairs, and changes nothing") {
    for (solver, setting) <- Seq(ClassicStep -> "GridDetector.maxPairs", SoftStep() -> "SoftStep.maxPairs") do
      val world = World()
      world.solver = solver
      for _ <- 1 to 10000 do world += ball(0.1, 0, 0).body
      val start = System.nanoTime()
      val error = intercept[IllegalStateException](world.step())
      error.getMessage should include(setting)
      error.getMessage should include("1000000 candidate pairs")
      (System.nanoTime() - start) / 1e9 should be < 30.0 // at once, not after filling the heap
      world.time shouldBe 0.0
      world.bodies.forall(_.pos == Vector2D.Null) shouldBe true
  }

  test("with maxPairs raised a pile is stepped; maxPairs must be at least 1") {
    def pile(balls: Int, limit: Int): World =
      val world = World()
      world.detector.asInstanceOf[GridDetector].maxPairs = limit
      for _ <- 1 to balls do world += ball(0.1, 0, 0).body
      world
    pile(5, 10).step() // 10 pairs: allowed
    intercept[IllegalStateException](pile(6, 10).step()).getMessage should include("more than 10 candidate pairs")
    pile(6, 15).step()
    intercept[IllegalArgumentException](pile(1, 0)).getMessage should include("maxPairs must be at least 1, got 0")
  }
