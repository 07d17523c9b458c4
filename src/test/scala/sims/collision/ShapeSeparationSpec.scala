package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.manifold.ManifoldFixtures.*
import sims.dynamics.Shape
import sims.geometry.{Projection, Vector2D}

/** ShapeSeparation against brute-force geometry: apart, the exact distance with a normal along
  * which it is the gap; overlapping, a negative depth; the same both ways round.
  */
class ShapeSeparationSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  private val gaps: Gen[Double] = Gen.oneOf(Gen.choose(-0.3, -1e-4), Gen.choose(1e-4, 2.0))

  private type Maker = (Double, Double) => Gen[Shape]
  private val kinds: Seq[(String, Maker)] = Seq(
    "circle" -> ((x, y) => circleAt(x, y)),
    "polygon" -> ((x, y) => polygonAt(x, y)),
    "capsule or edge" -> ((x, y) => capsuleAt(x, y)))

  /** The gap between the shapes' projections on the unit axis n, b's beyond a's. */
  private def gapAlong(a: Shape, b: Shape, n: Vector2D): Double = b.projectMin(n.x, n.y) - a.projectMax(n.x, n.y)

  for (nameA, makeA) <- kinds; (nameB, makeB) <- kinds do
    val pairs = pairsOf(makeA, makeB, gaps)
    test(s"$nameA and $nameB: apart, the exact distance and a unit normal along which it is the gap") {
      val separation = ShapeSeparation()
      forAll(pairs, minSuccessful(300)) { case (a, b) =>
        val expected = distance(a, b)
        whenever(expected > 1e-6) {
          separation.measure(a, b) shouldBe true
          separation.distance shouldBe expected +- 1e-9
          val n = Vector2D(separation.normalX, separation.normalY)
          n.length shouldBe 1.0 +- 1e-12
          gapAlong(a, b, n) shouldBe expected +- 1e-9
        }
      }
    }

    test(s"$nameA and $nameB: overlapping, a negative separation no deeper than the gap along its normal says") {
      val separation = ShapeSeparation()
      forAll(pairs, minSuccessful(300)) { case (a, b) =>
        whenever(distance(a, b) == 0) {
          separation.measure(a, b) shouldBe true
          separation.distance should be <= 1e-9
          val n = Vector2D(separation.normalX, separation.normalY)
          gapAlong(a, b, n) shouldBe separation.distance +- 1e-9
        }
      }
    }

    test(s"$nameA and $nameB: measured either way round, the same separation and opposite normals") {
      val ab = ShapeSeparation()
      val ba = ShapeSeparation()
      forAll(pairs, minSuccessful(200)) { case (a, b) =>
        ab.measure(a, b) shouldBe true
        ba.measure(b, a) shouldBe true
        ba.distance shouldBe ab.distance +- 1e-9
        if distance(a, b) > 1e-6 then
          ba.normalX shouldBe -ab.normalX +- 1e-9
          ba.normalY shouldBe -ab.normalY +- 1e-9
      }
    }

  test("a circle centred inside a box: minus the depth to the nearest side plus the radius, along that side's normal") {
    val separation = ShapeSeparation()
    separation.measure(box(1, 0.5, 0, 0), circle(0.25, 0.2, 0.3)) shouldBe true
    separation.distance shouldBe (-0.2 - 0.25) +- 1e-12
    (separation.normalX, separation.normalY) shouldBe (0.0, 1.0)
  }

  test("a shape of a user's kind is not measured, and nothing changes") {
    val user = new Shape:
      val density = 1.0
      def volume = 1.0
      def I = 1.0
      def AABB = sims.geometry.AABB(Vector2D(-1, -1), Vector2D(1, 1))
      def project(axis: Vector2D) = Projection(axis, -1, 1)
      def contains(point: Vector2D) = false
    val separation = ShapeSeparation()
    separation.measure(circle(1, 5, 0), circle(1, 0, 0)) shouldBe true
    separation.measure(user, circle(1, 0, 0)) shouldBe false
    separation.measure(box(1, 1, 0, 0), user) shouldBe false
    separation.distance shouldBe 3.0 +- 1e-12
  }

  test("polygonsWithin: when it says yes, the polygons are that close; near corners yes, near a side's middle no") {
    val separation = ShapeSeparation()
    forAll(pairsOf((x, y) => polygonAt(x, y), (x, y) => polygonAt(x, y), Gen.choose(0.0, 0.02)), Gen.choose(0.001, 0.02),
      minSuccessful(300)) { case ((a, b), reach) =>
      if separation.polygonsWithin(a, b, reach) then distance(a, b) should be <= reach + 1e-12
    }
    // Two boxes side by side, corners 4 mm apart, and a small box 1 mm from the middle of a big one's side.
    separation.polygonsWithin(box(0.5, 0.5, 0, 0), box(0.5, 0.5, 1.004, 0), 0.005) shouldBe true
    separation.polygonsWithin(box(0.5, 0.5, 0, 0), box(0.5, 0.5, 1.006, 0), 0.005) shouldBe false
    separation.polygonsWithin(box(2, 2, 0, 0), box(0.1, 0.1, 2.101, 0), 0.005) shouldBe false
    separation.polygonsWithin(box(0.5, 0.5, 0, 0), circle(0.5, 1.001, 0), 0.005) shouldBe false
  }
