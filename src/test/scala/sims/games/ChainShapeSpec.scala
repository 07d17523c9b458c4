package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, ChainSegment, Circle, Edge, Rectangle, Shape, World}
import sims.geometry.Vector2D
import sims.io.WorldCodec
import sims.robustness.StateHash
import sims.solver.SoftStep

/** The chain shape: a polyline of edges for terrain, smooth at its joins and one-sided. */
class ChainShapeSpec extends AnyFunSuite with Matchers:
  /** The points of a flat ground of `count` segments of `length` m along y = 0, from x = -1. */
  private def flat(count: Int, length: Double): Seq[Vector2D] = (0 to count).map(i => Vector2D(-1 + i * length, 0))

  /** A box without friction launched at 4 m/s along the ground made of `ground`'s shapes; the
    * largest vertical speed it has after settling (the first 0.5 s), and how far it went.
    */
  private def slide(ground: Seq[Shape]): (Double, Double) =
    val world = World()
    world.solver = SoftStep()
    world += Body(ground*)
    val box = Rectangle(0.25, 0.25).asBody
    box.pos = Vector2D(0, 0.25)
    box.shapes.head.friction = 0
    box.linearVelocity = Vector2D(4, 0)
    world += box
    var fastest = 0.0
    while world.time < 5 do
      world.step()
      if world.time > 0.5 then fastest = math.max(fastest, math.abs(box.linearVelocity.y))
    (fastest, box.pos.x)

  test("a box sliding along a chain of 100 short segments keeps its vertical speed under 1 cm/s (no ghost collisions)") {
    val points = flat(100, 0.25)
    val (chained, distance) = slide(ChainSegment.chain(points))
    info(f"chain: largest vertical speed ${100 * chained}%.4f cm/s over $distance%.1f m")
    chained should be < 0.01
    distance should be > 19.0 // it slid over (nearly) all 100 joins
    // The same ground as 100 separate edges: the box bumps on their corners.
    val edges = points.zip(points.tail).map((a, b) => Edge(a, b))
    val (bumped, _) = slide(edges)
    info(f"separate edges: largest vertical speed ${100 * bumped}%.4f cm/s")
    bumped should be > chained
  }

  test("a chain is one-sided: a ball thrown up from below passes through it, one dropped from above lands on it") {
    val world = World()
    world.solver = SoftStep()
    world += Body(ChainSegment.chain(Seq(Vector2D(-5, 0), Vector2D(0, 0), Vector2D(5, 0)))*)
    val up = Circle(0.2).asBody
    up.pos = Vector2D(-2, -1)
    up.linearVelocity = Vector2D(0, 8)
    world += up
    val down = Circle(0.2).asBody
    down.pos = Vector2D(2, 1)
    world += down
    var highest = up.pos.y
    for _ <- 1 to 120 do
      world.step()
      highest = math.max(highest, up.pos.y)
    highest should be > 1.0
    down.pos.y shouldBe 0.2 +- 0.02
  }

  test("a ball rolls down a curved chain and over its joins, always on it") {
    val world = World()
    world.solver = SoftStep()
    val points = (0 to 60).map(i => Vector2D(i * 0.2, 2 * math.cos(i * 0.2 / 12 * math.Pi) + 2))
    world += Body(ChainSegment.chain(points)*)
    val ball = Circle(0.2).asBody
    ball.pos = Vector2D(2, 2 * math.cos(math.Pi / 6) + 2 + 0.25)
    world += ball
    var lowestGap = Double.PositiveInfinity
    while ball.pos.x < 11.5 && world.time < 10 do // until near the chain's end
      world.step()
      val ground = 2 * math.cos(ball.pos.x / 12 * math.Pi) + 2
      lowestGap = math.min(lowestGap, ball.pos.y - ground)
    info(f"the ball reached x = ${ball.pos.x}%.2f m at ${world.time}%.2f s, its centre at least $lowestGap%.3f m above the curve")
    ball.pos.x should be >= 11.5
    lowestGap should be > 0.15 // on the chain (radius 0.2 m), never through it
  }

  test("a world with a chain is saved with the segments' neighbours and steps on to the same bits") {
    val world = World()
    world.solver = SoftStep()
    world += Body(ChainSegment.chain(flat(10, 0.5), loop = false)*)
    val box = Rectangle(0.2, 0.2).asBody
    box.pos = Vector2D(0, 0.3)
    box.linearVelocity = Vector2D(2, 0)
    world += box
    for _ <- 1 to 20 do world.step()
    val loaded = WorldCodec.load(WorldCodec.save(world))
    StateHash(loaded) shouldBe StateHash(world)
    loaded.shapes.collect { case c: ChainSegment => (c.previous, c.next) } shouldBe
      world.shapes.collect { case c: ChainSegment => (c.previous, c.next) }
    for _ <- 1 to 30 do
      world.step()
      loaded.step()
    StateHash(loaded) shouldBe StateHash(world)
  }

  test("chain: its segments and their neighbours, a loop's last segment joining the first, bad points refused") {
    val square = Seq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(1, 1), Vector2D(0, 1))
    val open = ChainSegment.chain(square)
    open.map(_.previous) shouldBe Seq(None, Some(Vector2D(0, 0)), Some(Vector2D(1, 0)))
    open.map(_.next) shouldBe Seq(Some(Vector2D(1, 1)), Some(Vector2D(0, 1)), None)
    val loop = ChainSegment.chain(square, loop = true)
    loop should have length 4
    loop.last.vertex2.x shouldBe 0.0 +- 1e-12
    loop.last.next shouldBe Some(Vector2D(1, 0))
    loop.head.previous shouldBe Some(Vector2D(0, 1))
    val few = intercept[IllegalArgumentException](ChainSegment.chain(Seq(Vector2D(0, 0))))
    few.getMessage should include("points")
    intercept[IllegalArgumentException](ChainSegment.chain(square.take(2), loop = true)).getMessage should include("loop")
    intercept[IllegalArgumentException](ChainSegment.chain(Seq(Vector2D(0, 0), Vector2D(0, 0)))).getMessage should include("twice")
    Body(open*).fixed shouldBe true
  }
