package sims.collision.manifold

import sims.collision.manifold.ManifoldFixtures.*
import sims.dynamics.{Circle, RoundedSegment}
import sims.geometry.Vector2D

/** Capsule-circle (and edge-circle) manifolds: hand-computed cases and the laws. */
class CapsuleCircleManifoldSpec extends ManifoldLaws:

  private def collide(a: RoundedSegment, b: Circle): Manifold =
    val manifold = Manifold()
    CapsuleCircleManifold.collide(a, b, SpeculativeDistance, manifold)
    manifold

  private def collide(a: Circle, b: RoundedSegment): Manifold =
    val manifold = Manifold()
    CapsuleCircleManifold.collide(a, b, SpeculativeDistance, manifold)
    manifold

  test("a circle on the side of a capsule: the normal straight out, the point midway") {
    // Core from (-1, 0) to (1, 0), radius 0.5; the circle's surface reaches 0.05 into it.
    shouldHave(collide(capsule(1, 0.5, 0, 0), circle(0.25, 0.5, 0.7)), Vector2D(0, 1), Point(0.5, 0.475, -0.05, 0))
  }

  test("a circle at a capsule's round end: the normal from the core's end") {
    val manifold = collide(capsule(1, 0.5, 0, 0), circle(0.25, 1.6, 0.3))
    val distance = math.hypot(0.6, 0.3)
    manifold.normalX shouldBe 0.6 / distance +- 1e-12
    manifold.normalY shouldBe 0.3 / distance +- 1e-12
    manifold.separation(0) shouldBe distance - 0.75 +- 1e-12
    manifold.x(0) shouldBe 1 + 0.6 / distance * (0.5 + (distance - 0.75) / 2) +- 1e-12
  }

  test("an edge: a capsule of radius 0; circle first turns the normal round") {
    shouldHave(collide(edge(-2, 0, 2, 0), circle(0.5, 0.3, 0.49)), Vector2D(0, 1), Point(0.3, -0.005, -0.01, 0))
    shouldHave(collide(circle(0.5, 0.3, 0.49), edge(-2, 0, 2, 0)), Vector2D(0, -1), Point(0.3, -0.005, -0.01, 0))
  }

  test("speculative and apart") {
    collide(capsule(1, 0.5, 0, 0), circle(0.25, 0, 0.76)).separation(0) shouldBe 0.01 +- 1e-12
    collide(capsule(1, 0.5, 0, 0), circle(0.25, 0, 0.78)).pointCount shouldBe 0
  }

  manifoldLaws("capsule and circle", pairsOf(capsuleAt, circleAt), collide)

  test("law: the separation is the signed gap of the surfaces, and swapping keeps the point") {
    forAll(pairsOf(capsuleAt, circleAt), minSuccessful(500)) { case (capsule, circle) =>
      val manifold = collide(capsule, circle)
      val gap = coreDistance(capsule, circle.x, circle.y) - capsule.radius - circle.radius
      if gap <= SpeculativeDistance then manifold.separation(0) shouldBe gap +- 1e-12
      val swapped = collide(circle, capsule)
      points(swapped) shouldBe points(manifold)
      swapped.normalX shouldBe -manifold.normalX
    }
  }
