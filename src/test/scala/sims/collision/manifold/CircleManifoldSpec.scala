package sims.collision.manifold

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.manifold.ManifoldFixtures.*
import sims.dynamics.Circle
import sims.geometry.Vector2D

/** Circle-circle manifolds: hand-computed cases and the laws of the narrowphase. */
class CircleManifoldSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private val tolerance = 1e-12

  private def collide(a: Circle, b: Circle): Manifold =
    val manifold = Manifold()
    CircleManifold.collide(a, b, SpeculativeDistance, manifold)
    manifold

  /** Checks the one point of `manifold` against the expected values. */
  private def shouldHavePoint(manifold: Manifold, normalX: Double, normalY: Double, x: Double, y: Double,
      separation: Double): Unit =
    manifold.pointCount shouldBe 1
    manifold.normalX shouldBe normalX +- tolerance
    manifold.normalY shouldBe normalY +- tolerance
    manifold.x(0) shouldBe x +- tolerance
    manifold.y(0) shouldBe y +- tolerance
    manifold.separation(0) shouldBe separation +- tolerance
    manifold.id(0) shouldBe 0

  test("overlapping: the point lies midway between the surfaces on the line of centres") {
    // Surfaces at x = 1 (A's) and x = 0.5 (B's): separation -0.5, point at 0.75.
    shouldHavePoint(collide(circle(1, 0, 0), circle(1, 1.5, 0)), 1, 0, 0.75, 0, -0.5)
    // A diagonal line of centres: n = (0.6, 0.8), d = 1, separation 1 - 1 - 0.5.
    shouldHavePoint(collide(circle(1, 1, 1), circle(0.5, 1.6, 1.8)), 0.6, 0.8, 1 + 0.6 * 0.75, 1 + 0.8 * 0.75, -0.5)
  }

  test("touching: separation 0, the point where the circles meet") {
    shouldHavePoint(collide(circle(1, 0, 0), circle(0.5, 0, 1.5)), 0, 1, 0, 1, 0)
  }

  test("speculative: apart by less than the speculative distance gives a point of positive separation") {
    // Surfaces at x = 1 and x = 1.01: the point halfway, at 1.005.
    shouldHavePoint(collide(circle(1, 0, 0), circle(1, 2.01, 0)), 1, 0, 1.005, 0, 0.01)
    // Just within the speculative distance still counts, just beyond it does not.
    collide(circle(1, 0, 0), circle(1, 2.0 + SpeculativeDistance - 1e-9, 0)).pointCount shouldBe 1
    collide(circle(1, 0, 0), circle(1, 2.0 + SpeculativeDistance + 1e-9, 0)).pointCount shouldBe 0
  }

  test("apart: farther than the speculative distance gives no point") {
    collide(circle(1, 0, 0), circle(1, 2.03, 0)).pointCount shouldBe 0
  }

  test("coincident centres: the fixed normal (0, 1)") {
    shouldHavePoint(collide(circle(1, 2, 3), circle(0.5, 2, 3)), 0, 1, 2, 3 + 0.25, -1.5)
  }

  private val circlePairs: Gen[(Circle, Circle)] = pairsOf(circleAt, circleAt)

  test("property: swapping the circles negates the normal and keeps the point") {
    forAll(circlePairs, minSuccessful(300)) { case (a, b) =>
      val ab = collide(a, b)
      val ba = collide(b, a)
      ba.pointCount shouldBe ab.pointCount
      if ab.pointCount == 1 then
        ba.normalX shouldBe -ab.normalX +- tolerance
        ba.normalY shouldBe -ab.normalY +- tolerance
        ba.x(0) shouldBe ab.x(0) +- 1e-9
        ba.y(0) shouldBe ab.y(0) +- 1e-9
        ba.separation(0) shouldBe ab.separation(0) +- tolerance
    }
  }

  test("property: moving the pair rigidly moves the point with it and keeps the separation") {
    forAll(circlePairs, Gen.choose(-math.Pi, math.Pi), position, minSuccessful(300)) { case ((a, b), angle, shift) =>
      val before = collide(a, b)
      val expected = points(before).map { p =>
        val moved = Vector2D(p.x, p.y).rotate(angle)
        (moved.x + shift.x, moved.y + shift.y, p.separation, p.id)
      }
      val normal = Vector2D(before.normalX, before.normalY).rotate(angle)
      moveRigidly(a, angle, shift.x, shift.y)
      moveRigidly(b, angle, shift.x, shift.y)
      val after = collide(a, b)
      after.pointCount shouldBe before.pointCount
      for (p, (x, y, separation, id)) <- points(after).zip(expected) do
        p.x shouldBe x +- 1e-9
        p.y shouldBe y +- 1e-9
        p.separation shouldBe separation +- 1e-9
        p.id shouldBe id
      if after.pointCount > 0 then
        after.normalX shouldBe normal.x +- 1e-9
        after.normalY shouldBe normal.y +- 1e-9
    }
  }

  test("property: the separation is the signed gap, the point lies within |s| / 2 of both outlines") {
    forAll(circlePairs, minSuccessful(500)) { case (a, b) =>
      val manifold = collide(a, b)
      val gapNow = math.hypot(b.x - a.x, b.y - a.y) - a.radius - b.radius
      if gapNow > SpeculativeDistance then manifold.pointCount shouldBe 0
      else
        manifold.pointCount shouldBe 1
        manifold.separation(0) shouldBe gapNow +- tolerance
        if distance(a, b) == 0 then manifold.separation(0) should be <= 0.0
        val half = math.abs(manifold.separation(0)) / 2 + 1e-9
        outlineDistance(a, manifold.x(0), manifold.y(0)) should be <= half
        outlineDistance(b, manifold.x(0), manifold.y(0)) should be <= half
    }
  }
