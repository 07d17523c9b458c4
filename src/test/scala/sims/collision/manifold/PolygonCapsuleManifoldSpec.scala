package sims.collision.manifold

import sims.collision.manifold.ManifoldFixtures.*
import sims.collision.manifold.PolygonManifold.{ReferenceIsB, SideShift}
import sims.dynamics.RoundedSegment
import sims.geometry.Vector2D

/** Polygon-capsule (and polygon-edge) manifolds: the polygon manifold with a capsule as a
  * two-vertex polygon with a radius. Hand-computed cases and the laws.
  */
class PolygonCapsuleManifoldSpec extends ManifoldLaws:

  private def collide(a: Polygon, b: RoundedSegment): Manifold =
    val manifold = Manifold()
    PolygonManifold.collide(a, b, SpeculativeDistance, LinearSlop, manifold)
    manifold

  private def collide(a: RoundedSegment, b: Polygon): Manifold =
    val manifold = Manifold()
    PolygonManifold.collide(a, b, SpeculativeDistance, LinearSlop, manifold)
    manifold

  // A capsule's vertices are its core's ends (0: the first, 1: the second); its side 0 is the
  // core's right side (facing down at rotation 0), side 1 its left.

  test("a capsule lying on a box: two points at its core's ends, midway between the surfaces") {
    // Core from (-0.3, 0.74) to (0.7, 0.74), radius 0.25: 0.01 into the box's top (y = 0.5).
    shouldHave(collide(box(1, 0.5, 0, 0), capsule(0.5, 0.25, 0.2, 0.74)), Vector2D(0, 1),
      Point(-0.3, 0.495, -0.01, 0), Point(0.7, 0.495, -0.01, 1))
  }

  test("a capsule's round end against a box's side: one point, the far end beyond reach") {
    // Core from (1.2, 0) to (2.2, 0), radius 0.5: 0.3 into the right side (x = 1, side 3).
    shouldHave(collide(box(1, 1, 0, 0), capsule(0.5, 0.5, 1.7, 0)), Vector2D(1, 0),
      Point(0.85, 0, -0.3, 3 << SideShift | 0))
  }

  test("a capsule's round end against a box's corner: the normal from the corner to the core's end") {
    val d = 0.3 * math.sqrt(2)
    val middle = 1 + 0.3 * (0.5 * (d - 0.5) / d)
    shouldHave(collide(box(1, 1, 0, 0), capsule(0.5, 0.5, 1.8, 1.3)), Vector2D(1, 1).unit,
      Point(middle, middle, d - 0.5, 0))
  }

  test("a box on an edge, edge first: two points on the edge's upper side") {
    // The edge's side 1 (facing up) runs from its vertex 1 to its vertex 0; the box's bottom
    // corners (vertices 2 and 3) lie 0.01 below it.
    shouldHave(collide(edge(-3, 0, 3, 0), box(0.5, 0.5, 0.2, 0.49)), Vector2D(0, 1),
      Point(-0.3, -0.005, -0.01, 1 << SideShift | 2), Point(0.7, -0.005, -0.01, 1 << SideShift | 3))
  }

  private val polygonFirst = pairsOf(polygonAt, capsuleAt)
  private val capsuleFirst = pairsOf(capsuleAt, polygonAt)

  manifoldLaws("polygon and capsule", polygonFirst, collide, (_, capsule, m) => tiltSlack(capsule, m))
  manifoldLaws("capsule and polygon", capsuleFirst, collide, (capsule, _, m) => tiltSlack(capsule, m))

  test("law: swapping negates the normal, keeps the points and toggles the reference bit, unless sides tie") {
    forAll(polygonFirst, minSuccessful(500)) { case (polygon, capsule) =>
      val ab = collide(polygon, capsule)
      val ba = collide(capsule, polygon)
      whenever(ab.pointCount > 0 && (ab.id(0) & ReferenceIsB) != (ba.id(0) & ReferenceIsB)) {
        points(ba) shouldBe points(ab).map(p => p.copy(id = p.id ^ ReferenceIsB))
        ba.normalX shouldBe -ab.normalX
        ba.normalY shouldBe -ab.normalY
      }
    }
  }
