package sims.collision.manifold

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.manifold.ManifoldFixtures.*
import sims.dynamics.Circle
import sims.geometry.Vector2D

/** Polygon-circle manifolds: hand-computed cases and the laws of the narrowphase. */
class PolygonCircleManifoldSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private val tolerance = 1e-12

  private def collide(polygon: Polygon, circle: Circle, lastSide: Int = -1): Manifold =
    val manifold = Manifold()
    PolygonCircleManifold.collide(polygon, circle, lastSide, SpeculativeDistance, manifold)
    manifold

  private def collide(circle: Circle, polygon: Polygon, lastSide: Int): Manifold =
    val manifold = Manifold()
    PolygonCircleManifold.collide(circle, polygon, lastSide, SpeculativeDistance, manifold)
    manifold

  /** Checks the one point of `manifold` against the expected values. */
  private def shouldHavePoint(manifold: Manifold, normalX: Double, normalY: Double, x: Double, y: Double,
      separation: Double, id: Int, side: Int): Unit =
    manifold.pointCount shouldBe 1
    manifold.normalX shouldBe normalX +- tolerance
    manifold.normalY shouldBe normalY +- tolerance
    manifold.x(0) shouldBe x +- tolerance
    manifold.y(0) shouldBe y +- tolerance
    manifold.separation(0) shouldBe separation +- tolerance
    manifold.id(0) shouldBe id
    manifold.polygonSide shouldBe side

  // A box's sides (Rectangle's vertex order): 0 top, 1 left, 2 bottom, 3 right.

  test("side contact, overlapping: the point midway between the side and the circle's surface") {
    // Top side at y = 1, circle surface at 1.3 - 0.5 = 0.8: separation -0.2, point at 0.9.
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.5, 0.2, 1.3)), 0, 1, 0.2, 0.9, -0.2, 0, 0)
    // Turned clockwise by 90 degrees, the box's top side 0 becomes its right side.
    shouldHavePoint(collide(box(1, 1, 0, 0, -math.Pi / 2), circle(0.5, 1.3, 0.2)), 1, 0, 0.9, 0.2, -0.2, 0, 0)
  }

  test("side contact, touching and speculative") {
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.5, -1.5, 0.3)), -1, 0, -1, 0.3, 0, 1, 1)
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.5, 0.4, -1.51)), 0, -1, 0.4, -1.005, 0.01, 2, 2)
  }

  test("apart: farther than the speculative distance gives no point") {
    val manifold = collide(box(1, 1, 0, 0), circle(0.5, 0, 1.53))
    manifold.pointCount shouldBe 0
    manifold.polygonSide shouldBe -1
  }

  test("vertex region: the normal from the vertex to the centre, id vertexCount + vertex") {
    // Centre (1.3, 1.4) is 0.5 from vertex 0 at (1, 1) along (0.6, 0.8); top side 0 separates most.
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.49, 1.3, 1.4)), 0.6, 0.8, 1.003, 1.004, 0.01, 4 + 0, 0)
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.6, 1.3, 1.4)), 0.6, 0.8, 0.97, 0.96, -0.1, 4, 0)
    // Beyond the end of the top side (from vertex 0 to vertex 1): vertex 1 at (-1, 1).
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.6, -1.3, 1.4)), -0.6, 0.8, -0.97, 0.96, -0.1, 4 + 1, 0)
  }

  test("vertex region: near a side's line but farther than the speculative distance from the vertex") {
    // The top side's line is 0.01 below the circle, the vertex 0.15 * sqrt 2 - 0.14 = 0.072 away.
    collide(box(1, 1, 0, 0), circle(0.14, 1.15, 1.15)).pointCount shouldBe 0
  }

  test("a centre inside a thick floor keeps last step's side, so the ball is not thrown through the floor") {
    val floor = box(5, 0.5, 0, 0) // 1 m thick
    val ball = circle(0.25, 0, -0.1) // centre 0.6 below the top, 0.4 above the bottom
    // Kept: the top side, 0.2 (< r) farther than the bottom; separation -0.6 - 0.25.
    shouldHavePoint(collide(floor, ball, lastSide = 0), 0, 1, 0, -0.1 + 0.175, -0.85, 0, 0)
    // Without a last side: the nearest side, the bottom.
    shouldHavePoint(collide(floor, ball, lastSide = -1), 0, -1, 0, -0.1 - 0.075, -0.65, 2, 2)
    // A last side that is no side of this polygon counts as none.
    collide(floor, ball, lastSide = 7).polygonSide shouldBe 2
  }

  test("a centre inside leaves last step's side when another is nearer by more than the radius") {
    val floor = box(5, 0.5, 0, 0)
    val ball = circle(0.25, 0, -0.3) // 0.8 below the top, 0.2 above the bottom: 0.6 > r
    // Midway between the bottom (y = -0.5) and the circle's surface beyond it (y = -0.05).
    shouldHavePoint(collide(floor, ball, lastSide = 0), 0, -1, 0, -0.275, -0.45, 2, 2)
  }

  test("a centre outside ignores last step's side") {
    shouldHavePoint(collide(box(1, 1, 0, 0), circle(0.5, 0.2, 1.3), lastSide = 2), 0, 1, 0.2, 0.9, -0.2, 0, 0)
  }

  test("circle first: the same point, separation and id, the normal from the circle to the polygon") {
    shouldHavePoint(collide(circle(0.5, 0.2, 1.3), box(1, 1, 0, 0), -1), 0, -1, 0.2, 0.9, -0.2, 0, 0)
    shouldHavePoint(collide(circle(0.49, 1.3, 1.4), box(1, 1, 0, 0), -1), -0.6, -0.8, 1.003, 1.004, 0.01, 4, 0)
    collide(circle(0.5, 0, 1.53), box(1, 1, 0, 0), -1).pointCount shouldBe 0
  }

  test("a user's own ConvexPolygon (default vertex and normal arrays)") {
    val triangle = Triangle(IndexedSeq(Vector2D(0, 0), Vector2D(2, 0), Vector2D(0, 2)))
    // The hypotenuse (side 1, from (2, 0) to (0, 2)) faces (1, 1) / sqrt 2; the centre is
    // sqrt 2 beyond it, so the separation is sqrt 2 - 1.4.
    val s = math.sqrt(2)
    val manifold = collide(triangle, circle(1.4, 2, 2))
    shouldHavePoint(manifold, 1 / s, 1 / s, 2 - (s + 1.4) / 2 / s, 2 - (s + 1.4) / 2 / s, s - 1.4, 1, 1)
  }

  private val pairs: Gen[(Polygon, Circle)] = pairsOf(polygonAt, circleAt)

  private val lastSide: Gen[Int] = Gen.choose(-1, 7)

  test("property: circle first gives the same point and id, the normal negated") {
    forAll(pairs, lastSide, minSuccessful(300)) { case ((polygon, circle), last) =>
      val polygonFirst = collide(polygon, circle, last)
      val circleFirst = collide(circle, polygon, last)
      points(circleFirst) shouldBe points(polygonFirst)
      circleFirst.polygonSide shouldBe polygonFirst.polygonSide
      circleFirst.normalX shouldBe -polygonFirst.normalX
      circleFirst.normalY shouldBe -polygonFirst.normalY
    }
  }

  test("property: moving the pair rigidly moves the point with it and keeps separation, id and side") {
    forAll(pairs, lastSide, Gen.choose(-math.Pi, math.Pi), position, minSuccessful(300)) {
      case ((polygon, circle), last, angle, shift) =>
        val before = collide(polygon, circle, last)
        moveRigidly(polygon, angle, shift.x, shift.y)
        moveRigidly(circle, angle, shift.x, shift.y)
        val after = collide(polygon, circle, last)
        after.pointCount shouldBe before.pointCount
        after.polygonSide shouldBe before.polygonSide
        if before.pointCount == 1 then
          val point = Vector2D(before.x(0), before.y(0)).rotate(angle) + shift
          val normal = Vector2D(before.normalX, before.normalY).rotate(angle)
          after.x(0) shouldBe point.x +- 1e-9
          after.y(0) shouldBe point.y +- 1e-9
          after.normalX shouldBe normal.x +- 1e-9
          after.normalY shouldBe normal.y +- 1e-9
          after.separation(0) shouldBe before.separation(0) +- 1e-9
          after.id(0) shouldBe before.id(0)
    }
  }

  test("property: with the centre outside, the separation is the signed distance of the surfaces") {
    forAll(pairs, minSuccessful(500)) { case (polygon, circle) =>
      whenever(!polygon.contains(circle.pos)) {
        val manifold = collide(polygon, circle)
        val signedGap = polygonOutlineDistance(polygon, circle.x, circle.y) - circle.radius
        if signedGap > SpeculativeDistance then manifold.pointCount shouldBe 0
        else
          manifold.pointCount shouldBe 1
          manifold.separation(0) shouldBe signedGap +- 1e-9
      }
    }
  }

  test("property: apart by more than the speculative distance, no point; overlapping, separation <= 0") {
    forAll(pairs, lastSide, minSuccessful(500)) { case ((polygon, circle), last) =>
      val manifold = collide(polygon, circle, last)
      val gapNow = distance(polygon, circle)
      if gapNow > SpeculativeDistance then manifold.pointCount shouldBe 0
      if gapNow == 0 then
        manifold.pointCount shouldBe 1
        manifold.separation(0) should be <= 0.0
    }
  }

  test("property: the point lies within |s| / 2 of both outlines") {
    forAll(pairs, minSuccessful(500)) { case (polygon, circle) =>
      val manifold = collide(polygon, circle)
      if manifold.pointCount == 1 then
        val half = math.abs(manifold.separation(0)) / 2 + 1e-9
        outlineDistance(polygon, manifold.x(0), manifold.y(0)) should be <= half
        outlineDistance(circle, manifold.x(0), manifold.y(0)) should be <= half
        math.hypot(manifold.normalX, manifold.normalY) shouldBe 1.0 +- tolerance
    }
  }
