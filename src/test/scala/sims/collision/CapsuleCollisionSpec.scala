package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.manifold.ManifoldFixtures
import sims.collision.manifold.ManifoldFixtures.{box, capsule, circle, edge, moveRigidly}
import sims.dynamics.{Edge, Shape, World}
import sims.geometry.{ConvexPolygon, Vector2D}

/** The classic step's collisions with capsules and edges: hand-computed cases through the
  * detector's lists, position correction's overlap with an edge, and the laws.
  */
class CapsuleCollisionSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private val detector = GridDetector(World())
  private def test(a: Shape, b: Shape): Boolean = detector.detectionMethods.find(_.isDefinedAt((a, b))).get((a, b))
  private def collide(a: Shape, b: Shape): Collision = detector.collisionMethods.find(_.isDefinedAt((a, b))).get((a, b))

  /** The points of `c`, rounded to 1e-9, in order. */
  private def rounded(c: Collision): List[(Double, Double)] =
    c.points.toList.map(p => (math.rint(p.x * 1e9) / 1e9, math.rint(p.y * 1e9) / 1e9))

  test("capsule-circle: the capsule is the reference in either order, the point on the circle") {
    val pill = capsule(1, 0.5, 0, 0)
    val ball = circle(0.25, 0.5, 0.7) // 0.05 into the capsule's side
    for c <- Seq(collide(pill, ball), collide(ball, pill)) do
      c shouldBe a[CapsuleCollision]
      c.shape1 shouldBe pill
      c.shape2 shouldBe ball
      c.normal shouldBe Vector2D(0, 1)
      rounded(c) shouldBe List((0.5, 0.45)) // centre - n r
    test(pill, circle(0.25, 0.5, 0.75)) shouldBe true // touching counts
    test(circle(0.25, 0.5, 0.76), pill) shouldBe false
  }

  test("capsule on an edge: two points on the capsule's outline, the edge (first) the reference") {
    val ground = edge(-3, 0, 3, 0)
    val pill = capsule(1, 0.25, 0.5, 0.24)
    val c = collide(ground, pill)
    c.shape1 shouldBe ground
    c.normal shouldBe Vector2D(0, 1)
    rounded(c) shouldBe List((-0.5, -0.01), (1.5, -0.01))
    val other = collide(pill, ground) // the first of two capsules is the reference
    other.shape1 shouldBe pill
    other.normal shouldBe Vector2D(0, -1)
    rounded(other) shouldBe List((-0.5, 0.0), (1.5, 0.0)) // on the edge
  }

  test("polygon-capsule: the polygon is the reference in either order") {
    val floor = box(1, 0.5, 0, 0)
    val pill = capsule(0.5, 0.25, 0.2, 0.74)
    for c <- Seq(collide(floor, pill), collide(pill, floor)) do
      c.shape1 shouldBe floor
      c.normal.y shouldBe 1.0 +- 1e-12
      rounded(c) shouldBe List((-0.3, 0.49), (0.7, 0.49))
    test(floor, capsule(0.5, 0.25, 0.2, 0.76)) shouldBe false
  }

  test("an edge counts as solid on its far side in the overlap of position correction") {
    val ground = edge(-3, 0, 3, 0)
    val block = box(0.5, 0.5, 0, 0.45) // 0.05 through the edge
    Collision.overlapAlong(ground, block, 0, 1) shouldBe 0.05 +- 1e-12
    Collision.overlapAlong(block, ground, 0, -1) shouldBe 0.05 +- 1e-12
    Collision.overlapAlong(ground, box(0.5, 0.5, 0, 0.6), 0, 1) shouldBe 0.0 // apart
    // A capsule's projection is its core's, widened by the radius.
    Collision.overlapAlong(block, capsule(1, 0.25, 0, 1.1), 0, 1) shouldBe 0.1 +- 1e-12
  }

  test("a pair without a capsule or an edge is not this collision's: the error names both classes") {
    intercept[IllegalArgumentException](CapsuleCollision(circle(1, 0, 0), circle(1, 0, 1))).getMessage shouldBe
      "no capsule contact for Circle and Circle"
    intercept[IllegalArgumentException](CapsuleCollision(box(1, 1, 0, 0), box(1, 1, 0, 1))).getMessage should
      include("Rectangle and Rectangle")
  }

  test("the detector's direct path and the partial functions give the same collision") {
    val world = World()
    val ground = edge(-3, 0, 3, 0)
    val pill = capsule(1, 0.25, 0.5, 0.24)
    world += ground.asBody
    world += pill.asBody
    world.detector.detect()
    val direct = world.collisions.head
    direct.shape1 shouldBe ground
    rounded(direct) shouldBe rounded(collide(ground, pill))
    direct.normal shouldBe collide(ground, pill).normal
  }

  private val shapes: Gen[Shape] = Gen.oneOf(
    ManifoldFixtures.capsuleAt(0, 0), ManifoldFixtures.circleAt(0, 0), ManifoldFixtures.polygonAt(0, 0))
  private val pairs: Gen[(Shape, Shape)] =
    for
      p <- ManifoldFixtures.position
      a <- ManifoldFixtures.capsuleAt(p.x, p.y)
      b <- shapes
      u <- ManifoldFixtures.direction
      g <- Gen.choose(-0.3, 0.05)
      capsuleFirst <- Gen.oneOf(true, false)
    yield
      ManifoldFixtures.placeAtGap(a, b, u, g)
      if capsuleFirst then (a, b) else (b, a)

  test("law: the test agrees with the collision, in either order, and with the shapes' distance") {
    forAll(pairs, minSuccessful(500)) { case (a, b) =>
      // Two edges never meet in a world (both are fixed), and the distance of two that cross
      // is a matter of rounding.
      whenever(!(a.isInstanceOf[Edge] && b.isInstanceOf[Edge])) {
        val c = CapsuleCollision(a, b)
        test(a, b) shouldBe (c.pointCount > 0)
        test(b, a) shouldBe test(a, b)
        val gap = ManifoldFixtures.distance(a, b)
        if gap > 1e-9 then test(a, b) shouldBe false
        // Exact where closest points decide (no polygon's separating axes).
        if !a.isInstanceOf[ConvexPolygon] && !b.isInstanceOf[ConvexPolygon] && gap == 0 then test(a, b) shouldBe true
        if c.pointCount > 0 then c.normal.length shouldBe 1.0 +- 1e-12
      }
    }
  }

  test("two edges that cross touch at one point wherever they are: a rigid move does not change it") {
    // Drawn by the rigid-move law (on Node's stream): the cores cross 0.05 m from the second
    // edge's first end, and what rounding left of their distance (about 1e-16 m, positive
    // or not) decided whether the pair had a point, unmoved or moved.
    val a = edge(-3.4950996865472206, 2.5119693250758584, -1.769995673436517, -0.4390304530020359)
    val b = edge(-2.944928891277082, 1.4647563868859739, -0.7175424437574671, 2.8079657923326837)
    val before = CapsuleCollision(a, b)
    before.pointCount shouldBe 1
    moveRigidly(a, 2.2371921015105842, 0.7911318190248671, 1.6466188175680818)
    moveRigidly(b, 2.2371921015105842, 0.7911318190248671, 1.6466188175680818)
    val after = CapsuleCollision(a, b)
    after.pointCount shouldBe 1
    val expected = before.points.head.rotate(2.2371921015105842) + Vector2D(0.7911318190248671, 1.6466188175680818)
    after.points.head.x shouldBe expected.x +- 1e-9
    after.points.head.y shouldBe expected.y +- 1e-9
  }

  test("law: moving the pair rigidly moves the collision with it") {
    forAll(pairs, Gen.choose(-math.Pi, math.Pi), ManifoldFixtures.position, minSuccessful(300)) {
      case ((a, b), angle, shift) =>
        val before = CapsuleCollision(a, b)
        val expected = before.points.toList.map(p => p.rotate(angle) + shift)
        val normal = before.normal.rotate(angle)
        moveRigidly(a, angle, shift.x, shift.y)
        moveRigidly(b, angle, shift.x, shift.y)
        val after = CapsuleCollision(a, b)
        after.shape1 shouldBe before.shape1
        after.points.size shouldBe expected.size
        for (p, q) <- after.points.toList.zip(expected) do
          p.x shouldBe q.x +- 1e-9
          p.y shouldBe q.y +- 1e-9
        if expected.nonEmpty then
          after.normal.x shouldBe normal.x +- 1e-9
          after.normal.y shouldBe normal.y +- 1e-9
    }
  }
