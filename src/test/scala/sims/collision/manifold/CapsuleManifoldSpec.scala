package sims.collision.manifold

import org.scalacheck.Gen
import sims.collision.manifold.CapsuleManifold.{ReferenceIsB, TwoPoints}
import sims.collision.manifold.ManifoldFixtures.*
import sims.dynamics.RoundedSegment
import sims.geometry.Vector2D

/** Capsule-capsule manifolds (edges among them): hand-computed cases and the laws. */
class CapsuleManifoldSpec extends ManifoldLaws:

  private def collide(a: RoundedSegment, b: RoundedSegment): Manifold =
    val manifold = Manifold()
    CapsuleManifold.collide(a, b, SpeculativeDistance, LinearSlop, manifold)
    manifold

  test("a capsule lying on an edge: two points, at the ends of its core") {
    // Core from (-0.5, 0.24) to (1.5, 0.24), radius 0.25: 0.01 into the edge along y = 0.
    shouldHave(collide(edge(-3, 0, 3, 0), capsule(1, 0.25, 0.5, 0.24)), Vector2D(0, 1),
      Point(-0.5, -0.005, -0.01, TwoPoints | 0), Point(1.5, -0.005, -0.01, TwoPoints | 1))
  }

  test("a capsule reaching beyond the end of an edge is clipped to the edge") {
    shouldHave(collide(edge(-3, 0, 1, 0), capsule(1, 0.25, 0.5, 0.24)), Vector2D(0, 1),
      Point(-0.5, -0.005, -0.01, TwoPoints | 0), Point(1, -0.005, -0.01, TwoPoints | 1))
  }

  test("the core that separates better is the reference; B's keeps the normal from A to B") {
    // B, longer and turned by 0.005 rad, above A: A's ends lie farther beyond B's line than
    // B's ends beyond A's, so B's side is the reference and A's core is clipped to it.
    val turn = 0.005
    val a = capsule(0.5, 0.25, 0, 0)
    val b = capsule(2, 0.25, 0, 0.49, turn)
    val normal = Vector2D(-math.sin(turn), math.cos(turn)) // B's side normal towards A, turned round
    def point(x: Double, id: Int): Point =
      val core = (Vector2D(x, 0) - Vector2D(0, 0.49)) dot -normal // A's end below B's line
      val q = Vector2D(x, 0) + normal * (0.5 * core) // midway: the radii are equal
      Point(q.x, q.y, core - 0.5, TwoPoints | ReferenceIsB | id)
    shouldHave(collide(a, b), normal, point(-0.5, 0), point(0.5, 1))
  }

  test("crossing capsules: one point, between the cores' closest points") {
    // Perpendicular cores 0.4 apart at their middles, radii 0.25: separation -0.1.
    shouldHave(collide(capsule(1, 0.25, 0, 0), capsule(1, 0.25, 0, 1.4, math.Pi / 2)), Vector2D(0, 1),
      Point(0, 0.25 - 0.05, -0.1, 3 * 2 + 0))
    // Cores that cross: A's side normal towards B's middle.
    val crossing = collide(capsule(1, 0.25, 0, 0), capsule(1, 0.25, 0, 0.5, math.Pi / 2))
    crossing.normalY shouldBe 1.0
    crossing.separation(0) shouldBe -0.5 +- 1e-12
  }

  test("end to end along one line: one point between the round ends") {
    // Cores end at x = 2 and start at x = 2.5; radii 0.3: 0.1 of overlap.
    shouldHave(collide(capsule(1, 0.3, 1, 0), capsule(1, 0.3, 3.5, 0)), Vector2D(1, 0),
      Point(2.25, 0, -0.1, 3 * 1 + 0))
  }

  test("apart: farther than the speculative distance gives no point") {
    collide(capsule(1, 0.25, 0, 0), capsule(1, 0.25, 0, 0.53)).pointCount shouldBe 0
    collide(capsule(1, 0.25, 0, 0), capsule(1, 0.25, 0, 0.515)).pointCount shouldBe 2
  }

  private val pairs = pairsOf(capsuleAt, capsuleAt)
  // Lying along each other, from overlapping to apart: where the two-point manifold is made.
  private def parallelPairs(largestTilt: Double): Gen[(RoundedSegment, RoundedSegment)] =
    for
      (a, b) <- pairsOf(capsuleAt, capsuleAt, Gen.choose(-0.1, SpeculativeDistance))
      tilt <- Gen.choose(-largestTilt, largestTilt)
    yield
      b.rotation = a.rotation + tilt
      (a, b)

  /** Cores that cross have no surfaces facing each other to be midway between; otherwise both
    * outlines may be tilted to the normal.
    */
  private def tilts(a: RoundedSegment, b: RoundedSegment, manifold: Manifold): Double =
    if segmentsMeet(a.vertex1, a.vertex2, b.vertex1, b.vertex2) then Double.PositiveInfinity
    else tiltSlack(a, manifold) + tiltSlack(b, manifold)

  manifoldLaws("any two", pairs, collide, tilts)
  manifoldLaws("lying along each other", parallelPairs(0.04), collide, tilts)

  test("law: apart and not lying along each other, the one separation is the exact gap; swapping keeps the point") {
    forAll(pairs, minSuccessful(500)) { case (a, b) =>
      val manifold = collide(a, b)
      val gap = segmentsDistance(a.vertex1, a.vertex2, b.vertex1, b.vertex2) - a.radius - b.radius
      // One point from the closest points (cores that cross take a side normal instead).
      whenever(manifold.pointCount == 1 && (manifold.id(0) & TwoPoints) == 0 && gap > -a.radius - b.radius) {
        manifold.separation(0) shouldBe gap +- 1e-9
        val swapped = collide(b, a)
        swapped.pointCount shouldBe 1
        swapped.x(0) shouldBe manifold.x(0) +- 1e-9
        swapped.y(0) shouldBe manifold.y(0) +- 1e-9
        swapped.normalX shouldBe -manifold.normalX +- 1e-9
      }
    }
  }

  test("law: two points: swapping keeps them and toggles the reference bit, unless both sides tie") {
    forAll(parallelPairs(0.005), minSuccessful(300), maxDiscardedFactor(10.0)) { case (a, b) =>
      val ab = collide(a, b)
      val ba = collide(b, a)
      whenever(ab.pointCount == 2 && ba.pointCount == 2 && (ab.id(0) & ReferenceIsB) != (ba.id(0) & ReferenceIsB)) {
        points(ba).map(p => (p.x, p.y, p.separation)) shouldBe points(ab).map(p => (p.x, p.y, p.separation))
        ba.normalX shouldBe -ab.normalX
      }
    }
  }
