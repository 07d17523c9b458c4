package sims.collision.broadphase

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.{PairFilter, RandomScenes}
import sims.dynamics.{Body, Circle, Shape, World}
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** The kept pairs give a step exactly the grid's pairs, in one order whatever the history, and
  * search only for the shapes that moved.
  */
class KeptPairsSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  /** Every collidable pair whose bounds overlap and that the filter accepts, by second shape, then first. */
  private def expected(world: World): Seq[(Int, Int)] =
    val shapes = world.shapeBuffer
    val pairs =
      for
        i <- shapes.indices
        j <- 0 until i
        if shapes(j).AABB.overlaps(shapes(i).AABB) && PairFilter.accepts(shapes(j), shapes(i))
      yield (j, i)
    pairs.sortBy((j, i) => (i, j))

  /** The pipeline's pairs through the kept pairs, bounds not enlarged (as the brute force's). */
  private def keptPairs(world: World, side: Double = 2.0, maxPairs: Int = 1000000): Seq[(Int, Int)] =
    val pipeline = world.collisionPipeline
    pipeline.findKeptPairs(world.shapeBuffer, side, maxPairs, "maxPairs", 0, 0, world.revision)
    val pairs = pipeline.pairs
    (0 until pairs.size).map(k => (pairs.first(k).worldIndex, pairs.second(k).worldIndex))

  private val shape: Gen[Shape] = RandomScenes.shape(kinds = 6)

  /** How shape k moves in a round: not at all, a jitter, a step that may leave its enlarged
    * bounds, or a jump across the scene.
    */
  private val move: Gen[Int] = Gen.frequency(5 -> 0, 3 -> 1, 2 -> 2, 1 -> 3)

  /** 40 balls of radius 0.5 in 4 rows of 10, 0.9 m apart: each overlaps its neighbours. */
  private def ballRows(): World =
    val world = World()
    for i <- 0 until 40 do
      val s = Circle(0.5, 1)
      s.pos = Vector2D(0.9 * (i % 10), 0.9 * (i / 10))
      world += s.asBody
    world

  test("after any moves and filter changes, the kept pairs are the pairs a brute force finds, in its order") {
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0, 7.0), Gen.listOfN(8 * 64, move), minSuccessful(30)) {
      (shapes, side, moves) =>
        val world = RandomScenes.scene(shapes, side, someNotCollidable = true)
        val bodies = world.bodies.filterNot(_.fixed)
        for round <- 0 until 8 do
          keptPairs(world, side) shouldBe expected(world)
          for (body, k) <- bodies.zipWithIndex do
            val kind = moves((64 * round + k) % moves.length)
            body.pos = body.pos +
              (kind match
                case 0 => Vector2D(0, 0)
                case 1 => Vector2D(1e-6 * (k % 3 - 1), 1e-6)
                case 2 => Vector2D(0.3 * (k % 3 - 1), -0.2)
                case _ => Vector2D(13.0 * (k % 5 - 2), 7.0 * (round % 3 - 1)))
          // Filter changes that do not change the world's revision, on a few shapes.
          val s = world.shapeBuffer((7 * round + 1) % world.shapeBuffer.length)
          round % 4 match
            case 0 => s.groupIndex = -1
            case 1 => s.collidable = !s.collidable
            case 2 => s.maskBits = 0
            case _ => s.groupIndex = 0; s.maskBits = sims.Defaults.MaskBits
        keptPairs(world, side) shouldBe expected(world)
    }
  }

  test("a pair a changed filter turns down returns when the filter accepts it again, with no shape moving") {
    val world = World()
    val a = Circle(1, 1); val b = Circle(1, 1)
    b.pos = Vector2D(1.5, 0)
    world += a.asBody
    world += b.asBody
    val c = Circle(1, 1)
    c.pos = Vector2D(3, 0)
    world += c.asBody
    keptPairs(world) shouldBe Seq((0, 1), (1, 2))
    a.groupIndex = -3; b.groupIndex = -3
    keptPairs(world) shouldBe Seq((1, 2))
    b.groupIndex = 0
    keptPairs(world) shouldBe Seq((0, 1), (1, 2))
    b.body.fixed = true; c.body.fixed = true
    keptPairs(world) shouldBe Seq((0, 1))
    c.body.fixed = false
    keptPairs(world) shouldBe Seq((0, 1), (1, 2))
  }

  test("only a search finds pairs, and only the moved shapes' partners are searched when few moved") {
    val world = ballRows()
    val kept = world.collisionPipeline.kept
    keptPairs(world) shouldBe expected(world)
    (kept.searches, kept.fullSearches) shouldBe (1, 1)
    // A jitter far inside the enlarged bounds: no search.
    world.bodies.foreach(b => b.pos = b.pos + Vector2D(1e-9, 0))
    keptPairs(world) shouldBe expected(world)
    (kept.searches, kept.fullSearches) shouldBe (1, 1)
    // Two shapes move far: their partners alone are searched.
    world.bodies(3).pos = Vector2D(20, 20)
    world.bodies(17).pos = Vector2D(0.3, 0.2)
    keptPairs(world) shouldBe expected(world)
    (kept.searches, kept.fullSearches) shouldBe (2, 1)
    // Half of them move: a full search.
    world.bodies.take(20).foreach(b => b.pos = b.pos + Vector2D(0, 5))
    keptPairs(world) shouldBe expected(world)
    (kept.searches, kept.fullSearches) shouldBe (3, 2)
    // A new body changes the world: a full search.
    world += Circle(0.5, 1).asBody
    keptPairs(world) shouldBe expected(world)
    (kept.searches, kept.fullSearches) shouldBe (4, 3)
  }

  test("a step fails past its limit of pairs, naming it, however many pairs its enlarged bounds would keep") {
    val world = World()
    for _ <- 0 until 30 do world += Circle(1, 1).asBody
    // 435 pairs, all at one place: past the kept pairs' limit (twice 200) and past 300.
    intercept[IllegalStateException](keptPairs(world, maxPairs = 200)).getMessage should
      include("more than 200 candidate pairs")
    intercept[IllegalStateException](keptPairs(world, maxPairs = 300)).getMessage should
      include("more than 300 candidate pairs")
    keptPairs(world, maxPairs = 435) shouldBe expected(world)
    // A row of balls 10 cm apart: no pairs, but 9 of enlarged bounds, past twice the limit 4.
    val row = World()
    for i <- 0 until 10 do
      val s = Circle(1, 1)
      s.pos = Vector2D(2.1 * i, 0)
      row += s.asBody
    keptPairs(row, maxPairs = 4) shouldBe empty
    keptPairs(row, maxPairs = 4) shouldBe empty
    keptPairs(row, maxPairs = 5) shouldBe empty
    row.collisionPipeline.kept.fullSearches shouldBe 3
  }

  test("soft-stepped stacks at rest find their pairs without a search") {
    val world = World()
    world.solver = SoftStep()
    world.enableSleep = false
    val ground = sims.dynamics.Rectangle(10, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    val floor = Body(ground)
    floor.fixed = true
    world += floor
    for i <- 0 until 60 do
      val s = sims.dynamics.Rectangle(0.1, 0.1, 1)
      s.pos = Vector2D(-1.5 + 0.3 * (i % 10), 0.1 + 0.2 * (i / 10))
      world += s.asBody
    for _ <- 0 until 120 do world.step()
    val kept = world.collisionPipeline.kept
    val before = kept.searches
    for _ <- 0 until 60 do world.step()
    kept.searches shouldBe before
    world.collisionPipeline.pairs.size shouldBe 60
    world.bodies.forall(_.linearVelocity.length < 0.01) shouldBe true
  }

  test("a shape that slowed down is searched again, and keeps only the partners its bounds now meet") {
    val world = ballRows()
    val pipeline = world.collisionPipeline
    val kept = pipeline.kept
    // Bounds stretched by how far each body moves in 0.1 s.
    def swept(): Seq[(Int, Int)] =
      pipeline.findKeptPairs(world.shapeBuffer, 2.0, 1000000, "maxPairs", 0, 0.1, world.revision)
      val pairs = pipeline.pairs
      (0 until pairs.size).map(k => (pairs.first(k).worldIndex, pairs.second(k).worldIndex))
    swept() shouldBe expected(world)
    val calm = kept.keptCount
    // Ball 15 at 30 m/s: its bounds 3 m longer, over its whole column.
    world.bodies(15).linearVelocity = Vector2D(0, 30)
    swept().size should be > expected(world).size
    kept.keptCount should be > calm
    (kept.searches, kept.fullSearches) shouldBe (2, 1)
    // At rest again, within its enlarged bounds but far smaller: searched again, alone.
    world.bodies(15).linearVelocity = Vector2D(0, 0)
    swept() shouldBe expected(world)
    kept.keptCount shouldBe calm
    (kept.searches, kept.fullSearches) shouldBe (3, 1)
    swept() shouldBe expected(world)
    kept.searches shouldBe 3
  }
