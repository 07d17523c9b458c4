package sims.collision.manifold

import org.scalacheck.Gen
import sims.collision.manifold.ManifoldFixtures.*
import sims.collision.manifold.PolygonManifold.{ReferenceIsB, SideShift}
import sims.dynamics.Rectangle
import sims.geometry.Vector2D

/** Polygon-polygon manifolds: hand-computed cases and the laws of the narrowphase. */
class PolygonManifoldSpec extends ManifoldLaws:

  private val tolerance = 1e-12

  private def collide(a: Polygon, b: Polygon): Manifold =
    val manifold = Manifold()
    PolygonManifold.collide(a, b, SpeculativeDistance, LinearSlop, manifold)
    manifold

  /** Checks normal and points of `manifold` (points in order) against the expected values. */
  private def shouldBe(manifold: Manifold, normal: Vector2D, expected: Point*): Unit =
    manifold.pointCount shouldBe expected.length
    manifold.normalX shouldBe normal.x +- tolerance
    manifold.normalY shouldBe normal.y +- tolerance
    for (point, wanted) <- points(manifold).zip(expected) do
      point.x shouldBe wanted.x +- tolerance
      point.y shouldBe wanted.y +- tolerance
      point.separation shouldBe wanted.separation +- tolerance
      point.id shouldBe wanted.id

  // Rectangle's vertices: 0 upper right, 1 upper left, 2 lower left, 3 lower right; its sides
  // 0 top, 1 left, 2 bottom, 3 right. A box A under a box B with A's top as reference side:
  // incident side B's bottom (vertex 2 to vertex 3), ids 0 << SideShift | 2 and | 3.

  test("box resting on a box, overlapping: two points midway, on the reference side A's top") {
    val floor = box(1, 0.5, 0, 0)
    val block = box(0.5, 0.5, 0.2, 0.99) // bottom at 0.49: 0.01 into the floor
    shouldBe(collide(floor, block), Vector2D(0, 1), Point(-0.3, 0.495, -0.01, 2), Point(0.7, 0.495, -0.01, 3))
  }

  test("regression: exactly touching boxes give the face normal and two points (the classic narrowphase went sideways)") {
    val floor = box(1, 0.5, 0, 0)
    val block = box(0.5, 0.5, 0.2, 1.0)
    shouldBe(collide(floor, block), Vector2D(0, 1), Point(-0.3, 0.5, 0, 2), Point(0.7, 0.5, 0, 3))
    // Equal boxes exactly side by side: the normal is (1, 0), not (0, 1).
    shouldBe(collide(box(1, 1, 0, 0), box(1, 1, 2, 0.5)), Vector2D(1, 0),
      Point(1, 1, 0, 3 << SideShift | 1), Point(1, -0.5, 0, 3 << SideShift | 2))
  }

  test("speculative: apart by less than the speculative distance, two points of positive separation") {
    val floor = box(1, 0.5, 0, 0)
    val block = box(0.5, 0.5, 0.2, 1.01)
    shouldBe(collide(floor, block), Vector2D(0, 1), Point(-0.3, 0.505, 0.01, 2), Point(0.7, 0.505, 0.01, 3))
  }

  test("apart: farther than the speculative distance gives no point") {
    collide(box(1, 0.5, 0, 0), box(0.5, 0.5, 0.2, 1.03)).pointCount shouldBe 0
    collide(box(1, 0.5, 0, 0), box(0.5, 0.5, 5, 5)).pointCount shouldBe 0
  }

  test("a box wider than its support is clipped to the support's side planes") {
    // Both choices of reference tie; A (the small block on top) is kept. Its bottom clips the
    // floor's top to x in [-0.3, 0.7]; the points are where they are in the other order.
    val block = box(0.5, 0.5, 0.2, 0.99)
    val floor = box(1, 0.5, 0, 0)
    shouldBe(collide(block, floor), Vector2D(0, -1),
      Point(0.7, 0.495, -0.01, 2 << SideShift | 0), Point(-0.3, 0.495, -0.01, 2 << SideShift | 1))
  }

  test("box resting on a rotated box: the same contact turned with the pair") {
    val angle = 0.3
    val (c, s) = (math.cos(angle), math.sin(angle))
    def turned(x: Double, y: Double) = Vector2D(c * x - s * y, s * x + c * y)
    val floor = box(1, 0.5, 0, 0, angle)
    val block = box(0.5, 0.5, 0, 0, angle)
    block.pos = turned(0.2, 0.99)
    val p1 = turned(-0.3, 0.495)
    val p2 = turned(0.7, 0.495)
    shouldBe(collide(floor, block), turned(0, 1), Point(p1.x, p1.y, -0.01, 2), Point(p2.x, p2.y, -0.01, 3))
  }

  test("a box tilted onto its corner: one point; in the other order B is the reference") {
    val floor = box(2, 0.5, 0, 0)
    val tilted = box(0.5, 0.5, 0, 0.49 + 0.5 * math.sqrt(2), math.Pi / 4) // lowest corner (vertex 2) at 0.49
    // The incident side's other end is far above the speculative distance: dropped.
    shouldBe(collide(floor, tilted), Vector2D(0, 1), Point(0, 0.495, -0.01, 2))
    shouldBe(collide(tilted, floor), Vector2D(0, -1), Point(0, 0.495, -0.01, ReferenceIsB | 2))
    // Tilted 0.01 above the floor: one speculative point.
    tilted.pos = Vector2D(0, 0.51 + 0.5 * math.sqrt(2))
    shouldBe(collide(floor, tilted), Vector2D(0, 1), Point(0, 0.505, 0.01, 2))
  }

  test("corner near corner: one point between the corners, their true distance and direction") {
    // A's top side (0) ties with its right side and is kept; B's vertex 2 is nearest A's vertex 0.
    val d = 0.01 * math.sqrt(2)
    shouldBe(collide(box(1, 1, 0, 0), box(1, 1, 2.01, 2.01)), Vector2D(1, 1).unit, Point(1.005, 1.005, d, 2))
    // In the other order B's left side (1) is the reference, A's vertex 0 the incident one.
    shouldBe(collide(box(1, 1, 2.01, 2.01), box(1, 1, 0, 0)), Vector2D(-1, -1).unit,
      Point(1.005, 1.005, d, 1 << SideShift | 0))
    // The face separation 0.015 is within the speculative distance, the corners' 0.0212 is not.
    val beyond = collide(box(1, 1, 0, 0), box(1, 1, 2.015, 2.015))
    beyond.pointCount shouldBe 0
    (beyond.normalX, beyond.normalY) shouldBe (0.0, 0.0) // no contact, no normal
  }

  /** A wide triangle above box(1, 1) at the origin: its bottom side from (-2, 0.99) rises by
    * 4 `slope` to (2, 0.99 + 4 slope), its apex at (0, 3). A's top separates by -0.01 (at the
    * triangle's vertex 0), the triangle's bottom by (slope - 0.01) / sqrt(1 + slope^2) (at A's
    * vertex 1): better than A's by about `slope`.
    */
  private def wedge(slope: Double): Triangle =
    Triangle(IndexedSeq(Vector2D(-2, 0.99), Vector2D(2, 0.99 + 4 * slope), Vector2D(0, 3)))

  test("the reference stays on A unless B separates better by more than 0.1 linearSlop") {
    // Better by 0.0003 < 0.0005: A's top clips the triangle's bottom to x in [-1, 1].
    shouldBe(collide(box(1, 1, 0, 0), wedge(0.0003)), Vector2D(0, 1),
      Point(-1, 0.9903 + 0.0097 / 2, -0.0097, 0), Point(1, 0.9909 + 0.0091 / 2, -0.0091, 1))
    // Better by 0.001: the triangle's bottom (side 0) is the reference, A's top (vertex 0 to 1)
    // the incident side; the normal still points from A to B.
    val slope = 0.001
    val length = math.sqrt(1 + slope * slope)
    val normal = Vector2D(-slope, 1) / length // the triangle's side normal turned round
    val separation0 = (3 * slope - 0.01) / length
    val separation1 = (slope - 0.01) / length
    val p0 = Vector2D(1, 1) + normal * (separation0 / 2) // q - n s / 2, n the triangle's normal
    val p1 = Vector2D(-1, 1) + normal * (separation1 / 2)
    shouldBe(collide(box(1, 1, 0, 0), wedge(slope)), normal,
      Point(p0.x, p0.y, separation0, ReferenceIsB | 0), Point(p1.x, p1.y, separation1, ReferenceIsB | 1))
  }

  // Random pairs, from deep overlap to farther apart than the speculative distance.
  private val pairs: Gen[(Polygon, Polygon)] = pairsOf(polygonAt, polygonAt)

  /** The best separation of each polygon's sides from the other. */
  private def separations(a: Polygon, b: Polygon): (Double, Double) =
    val sideA = PolygonManifold.bestSide(a.vertexXs, a.vertexYs, a.sideNormalXs, a.sideNormalYs, b.vertexXs, b.vertexYs)
    val sideB = PolygonManifold.bestSide(b.vertexXs, b.vertexYs, b.sideNormalXs, b.sideNormalYs, a.vertexXs, a.vertexYs)
    (PolygonManifold.sideSeparation(a.vertexXs, a.vertexYs, a.sideNormalXs, a.sideNormalYs, sideA, b.vertexXs, b.vertexYs),
      PolygonManifold.sideSeparation(b.vertexXs, b.vertexYs, b.sideNormalXs, b.sideNormalYs, sideB, a.vertexXs, a.vertexYs))

  test("property: swapping A and B negates the normal, keeps the points and toggles the reference bit of the ids") {
    forAll(pairs, minSuccessful(500)) { case (a, b) =>
      val (separationA, separationB) = separations(a, b)
      // Within 0.1 linearSlop of each other both orders keep their own first polygon.
      whenever(math.abs(separationA - separationB) > 0.1 * LinearSlop + 1e-9) {
        val ab = collide(a, b)
        val ba = collide(b, a)
        points(ba) shouldBe points(ab).map(p => p.copy(id = p.id ^ ReferenceIsB))
        ba.normalX shouldBe -ab.normalX
        ba.normalY shouldBe -ab.normalY
      }
    }
  }

  // Rigid motion, points midway between the outlines, gaps and overlaps: the laws of every
  // manifold function.
  manifoldLaws("two polygons", pairs, collide)

  test("property: overlapping pairs have a point of separation <= 0; apart ones none below their distance") {
    forAll(pairs, minSuccessful(500)) { case (a, b) =>
      val manifold = collide(a, b)
      val separationsNow = points(manifold).map(_.separation)
      val gapNow = distance(a, b)
      val (separationA, separationB) = separations(a, b)
      if separationA < -1e-9 && separationB < -1e-9 then // overlapping, not merely touching
        separationsNow should not be empty
        separationsNow.min should be <= 0.0
      if gapNow > 0 then
        for s <- separationsNow do s should be >= gapNow - 1e-9 // never negative, never short of the gap
      if gapNow > SpeculativeDistance then manifold.pointCount shouldBe 0
    }
  }

  // A box resting on another at any angle, both from the same random generator of sizes.
  private val restingPairs: Gen[(Rectangle, Rectangle)] =
    for
      floorHalfWidth <- Gen.choose(0.2, 3.0)
      floorHalfHeight <- Gen.choose(0.1, 1.0)
      blockHalfWidth <- Gen.choose(0.1, 1.0)
      blockHalfHeight <- Gen.choose(0.1, 1.0)
      offset <- Gen.choose(-0.9, 0.9).map(_ * (floorHalfWidth + blockHalfWidth - 0.05))
      angle <- Gen.choose(-math.Pi, math.Pi)
      centre <- position
    yield
      val floor = box(floorHalfWidth, floorHalfHeight, centre.x, centre.y, angle)
      val block = box(blockHalfWidth, blockHalfHeight, 0, 0, angle)
      block.pos = centre + Vector2D(offset, floorHalfHeight + blockHalfHeight).rotate(angle)
      (floor, block)

  test("property: the ids of a resting box survive a perturbation of 1e-6 m and 1e-6 rad") {
    val perturbation = Gen.choose(-1e-6, 1e-6)
    forAll(restingPairs, perturbation, perturbation, perturbation, minSuccessful(300)) {
      case ((floor, block), dx, dy, turn) =>
        val before = collide(floor, block)
        before.pointCount shouldBe 2
        before.id.toSet shouldBe Set(2, 3) // the floor's top against the block's bottom corners
        block.pos = block.pos + Vector2D(dx, dy)
        block.rotation = block.rotation + turn
        val after = collide(floor, block)
        after.pointCount shouldBe 2
        after.id.toSet shouldBe before.id.toSet
    }
  }

  test("a user's own ConvexPolygon collides through ConvexPolygon's default arrays") {
    val triangle = Triangle(IndexedSeq(Vector2D(-1, 0.49), Vector2D(1, 0.49), Vector2D(0, 2)))
    shouldBe(collide(box(2, 0.5, 0, 0), triangle), Vector2D(0, 1), Point(-1, 0.495, -0.01, 0), Point(1, 0.495, -0.01, 1))
  }
