package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Circle, Rectangle, Shape, World}
import sims.geometry.{AABB, ConvexPolygon, Projection, Vector2D}

/** The world's queries against brute force over random scenes (ray casts to the exact fraction),
  * their freshness after moves, filters, user shapes and bad input.
  */
class ShapeQueriesSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private val shape: Gen[Shape] = RandomScenes.shape(kinds = 6)
  private def scene(shapes: Seq[Shape], gridSide: Double): World =
    RandomScenes.scene(shapes, gridSide, someNotCollidable = true) // queries see every shape

  private val point: Gen[Vector2D] = for x <- Gen.choose(-25.0, 25.0); y <- Gen.choose(-35.0, 25.0) yield Vector2D(x, y)
  private val ray: Gen[(Vector2D, Vector2D)] =
    for
      from <- point
      length <- Gen.oneOf(Gen.choose(0.1, 2.0), Gen.choose(2.0, 80.0))
      angle <- Gen.choose(-math.Pi, math.Pi)
    yield (from, from + Vector2D(length * math.cos(angle), length * math.sin(angle)))

  /** Every shape's own hit, brute force: (fraction, world index) in order. */
  private def bruteForce(world: World, from: Vector2D, to: Vector2D): Seq[(Double, Int)] =
    world.shapes.flatMap(s => s.rayCast(from, to).map(h => (h.fraction, s.worldIndex))).sorted

  test("ray casts find exactly the hits of every shape's own cast, the nearest first") {
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0, 7.0), Gen.listOfN(10, ray), minSuccessful(40)) {
      (shapes, side, rays) =>
        val world = scene(shapes, side)
        for (from, to) <- rays do
          val expected = bruteForce(world, from, to)
          val all = world.rayCastAll(from, to)
          all.map(h => (h.fraction, h.shape.worldIndex)) shouldBe expected
          world.rayCast(from, to).map(h => (h.fraction, h.shape.worldIndex)) shouldBe expected.headOption
          for h <- all do
            h.point.x shouldBe from.x + h.fraction * (to.x - from.x)
            h.normal.length shouldBe 1.0 +- 1e-12
    }
  }

  test("box queries and point queries find exactly the shapes brute force finds, in world order") {
    val box =
      for
        corner <- point
        w <- Gen.oneOf(Gen.choose(0.0, 1.0), Gen.choose(1.0, 60.0))
        h <- Gen.choose(0.0, 10.0)
      yield AABB(corner, corner + Vector2D(w, h))
    forAll(Gen.listOfN(60, shape), Gen.oneOf(0.5, 2.0), Gen.listOfN(5, box), Gen.listOfN(5, point), minSuccessful(30)) {
      (shapes, side, boxes, points) =>
        val world = scene(shapes, side)
        for b <- boxes do world.query(b) shouldBe world.shapes.filter(_.AABB.overlaps(b))
        // Points on shapes, and anywhere.
        for p <- points ++ world.shapes.take(5).map(_.pos) do world.shapesAt(p) shouldBe world.shapes.filter(_.contains(p))
    }
  }

  test("shapes far apart: a ray across them checks their bounds instead of walking billions of cells") {
    val world = World()
    for x <- Seq(-1e9, -3.0, 0.0, 4.0, 1e9) do
      val ball = Circle(0.5, 1)
      ball.pos = Vector2D(x, 0)
      world += ball.asBody
    val from = Vector2D(-2e9, 0.1)
    val to = Vector2D(2e9, 0.1)
    world.rayCastAll(from, to).map(_.shape.pos.x) shouldBe Seq(-1e9, -3.0, 0.0, 4.0, 1e9)
    world.rayCast(Vector2D(-2, 0.1), to).map(_.shape.pos.x) shouldBe Some(0.0)
  }

  test("queries see bodies where they are now: after a step, a move, a restore, a body joining or leaving") {
    val world = World()
    val ball = Circle(0.5, 1)
    world += ball.asBody
    def hitAt(x: Double): Boolean = world.shapesAt(Vector2D(x, 0)).nonEmpty
    val start = world.snapshot()
    hitAt(0) shouldBe true
    world.gravity = Vector2D(0, 0)
    ball.body.linearVelocity = Vector2D(60, 0)
    world.step() // 1 m to the right
    hitAt(0) shouldBe false
    hitAt(1) shouldBe true
    ball.body.pos = Vector2D(5, 0)
    hitAt(5) shouldBe true
    world.restore(start)
    hitAt(0) shouldBe true
    val other = Circle(0.5, 1)
    other.pos = Vector2D(10, 0)
    world += other.asBody
    hitAt(10) shouldBe true
    world -= other.body
    hitAt(10) shouldBe false
    val plank = Rectangle(1, 0.1, 1)
    plank.pos = Vector2D(20, 0)
    world += plank.asBody
    def top: Option[Double] = world.rayCast(Vector2D(20, 5), Vector2D(20, -5)).map(_.point.y)
    top.get shouldBe 0.1 +- 1e-12
    plank.body.rotation = math.Pi / 2 // stood on end
    top.get shouldBe 1.0 +- 1e-12
  }

  test("the filter decides which shapes count; the nearest accepted one is hit") {
    val world = World()
    val near = Circle(0.5, 1)
    near.pos = Vector2D(2, 0)
    val far = Circle(0.5, 1)
    far.pos = Vector2D(5, 0)
    far.categoryBits = 2
    world += near.asBody
    world += far.asBody
    world.rayCast(Vector2D.Null, Vector2D(10, 0)).map(_.shape) shouldBe Some(near)
    world.rayCast(Vector2D.Null, Vector2D(10, 0), s => (s.categoryBits & 2) != 0).map(_.shape) shouldBe Some(far)
    world.rayCastAll(Vector2D.Null, Vector2D(10, 0)).map(_.shape) shouldBe Seq(near, far)
    world.query(AABB(Vector2D(0, -1), Vector2D(10, 1)), _ ne near) shouldBe Seq(far)
    world.shapesAt(Vector2D(2, 0), _ => false) shouldBe empty
  }

  /** A plate of a user's kind, 2 m wide, casting itself as its top face only. */
  private final class Plate extends Shape:
    val density = 1.0
    val volume = 0.2
    val I = 1.0
    def AABB = sims.geometry.AABB(Vector2D(x - 1, y - 0.1), Vector2D(x + 1, y))
    def project(axis: Vector2D) = Projection(axis, 0, 0)
    def contains(point: Vector2D) = AABB.minVertex.x <= point.x && point.x <= AABB.maxVertex.x &&
      AABB.minVertex.y <= point.y && point.y <= AABB.maxVertex.y
    override def rayCast(from: Vector2D, to: Vector2D): Option[RayHit] =
      val t = (y - from.y) / (to.y - from.y)
      val at = from + (to - from) * t
      if t >= 0 && t <= 1 && math.abs(at.x - x) <= 1 then Some(RayHit(this, at, Vector2D(0, 1), t)) else None

  /** A shape of a user's kind without a cast of its own. */
  private final class Blob extends Shape:
    val density = 1.0
    val volume = 1.0
    val I = 1.0
    def AABB = sims.geometry.AABB(Vector2D(x - 1, y - 1), Vector2D(x + 1, y + 1))
    def project(axis: Vector2D) = Projection(axis, 0, 0)
    def contains(point: Vector2D) = (point - pos).length <= 1

  /** A user's ConvexPolygon: a unit triangle, cast through ConvexPolygon's arrays. */
  private final class Wedge extends Shape with ConvexPolygon:
    val density = 1.0
    val volume = 0.5
    val I = 1.0
    def vertices = IndexedSeq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(0, 1)).map(_ + pos)

  test("user shapes: their own cast counts, a shape without one is missed, a ConvexPolygon is cast") {
    val world = World()
    val plate = Plate()
    plate.pos = Vector2D(0, -1)
    val blob = Blob()
    blob.pos = Vector2D(0, 2)
    val wedge = Wedge()
    wedge.pos = Vector2D(5, 0)
    world += plate.asBody
    world += blob.asBody
    world += wedge.asBody
    world.rayCast(Vector2D(0, 5), Vector2D(0, -5)).map(h => (h.shape, h.fraction)) shouldBe Some((plate, 0.6))
    blob.rayCast(Vector2D(0, 5), Vector2D(0, -5)) shouldBe None
    world.shapesAt(Vector2D(0, 2)) shouldBe Seq(blob) // found by its bounds and `contains`
    world.rayCast(Vector2D(4, 0.25), Vector2D(8, 0.25)).map(h => (h.shape, h.normal)) shouldBe Some((wedge, Vector2D(-1, 0)))
  }

  test("a user's cast beyond the nearest hit so far is not taken; a world with another detector queries too") {
    val world = World(w =>
      new Detector:
        def world = w
        def collisions = IndexedSeq.empty
        def detect(): Unit = ())
    val ball = Circle(0.5, 1)
    ball.pos = Vector2D(0, 2)
    val plate = Plate()
    plate.pos = Vector2D(0, -1)
    world += ball.asBody
    world += plate.asBody
    world.rayCast(Vector2D(0, 5), Vector2D(0, -5)).map(_.shape) shouldBe Some(ball)
    world.rayCastAll(Vector2D(0, 5), Vector2D(0, -5)).map(_.shape) shouldBe Seq(ball, plate)
  }

  test("bad input fails naming the argument") {
    val world = World()
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(world.rayCast(Vector2D(Double.NaN, 0), Vector2D.Null)) should include("from must be finite")
    message(world.rayCastAll(Vector2D.Null, null)) should include("to must not be null")
    message(world.rayCast(Vector2D.Null, Vector2D(1, 0), null)) should include("filter must not be null")
    message(world.query(AABB(Vector2D(1, 0), Vector2D(0, 1)))) should include("box must have its minVertex")
    message(world.query(null)) should include("box must not be null")
    message(world.shapesAt(Vector2D(0, Double.PositiveInfinity))) should include("point must be finite")
    world.rayCast(Vector2D.Null, Vector2D.Null) shouldBe None // no length, nothing entered
  }
