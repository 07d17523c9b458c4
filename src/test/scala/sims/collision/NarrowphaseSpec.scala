package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.Close
import sims.dynamics.{Circle, Rectangle, Shape}
import sims.geometry.{ConvexPolygon, Vector2D}

/** Each narrowphase case with hand-computed normals and points. */
class NarrowphaseSpec extends AnyFunSuite with Matchers:

  private def circle(r: Double, x: Double, y: Double): Circle =
    val c = Circle(r, 1); c.pos = Vector2D(x, y); c.asBody; c

  private def box(hw: Double, hh: Double, x: Double, y: Double, rotation: Double = 0): Rectangle =
    val b = Rectangle(hw, hh, 1); b.pos = Vector2D(x, y); b.rotation = rotation; b.asBody; b

  private val detector = GridDetector(sims.dynamics.World())
  private def test(a: Shape, b: Shape): Boolean = detector.detectionMethods.find(_.isDefinedAt((a, b))).get((a, b))
  private def collide(a: Shape, b: Shape): Collision = detector.collisionMethods.find(_.isDefinedAt((a, b))).get((a, b))

  test("circle-circle: overlapping, touching, separated") {
    val c1 = circle(1, 0, 0)
    val c2 = circle(1, 1.5, 0)
    test(c1, c2) shouldBe true
    val c = collide(c1, c2)
    c shouldBe a[CircleCollision]
    c.shape1 shouldBe c1
    c.shape2 shouldBe c2
    c.normal shouldBe Vector2D(1, 0)
    c.points.toList shouldBe List(Vector2D(0.5, 0))
    test(c1, circle(1, 0, 2)) shouldBe true // touching
    collide(c1, circle(1, 0, 2)).points.toList shouldBe List(Vector2D(0, 1))
    test(c1, circle(1, 2.01, 0)) shouldBe false
  }

  test("circle-circle: the normal points from the first to the second centre") {
    val c = collide(circle(1, 1, 1), circle(0.5, 1 + 0.6, 1 + 0.8))
    Close(c.normal, Vector2D(0.6, 0.8), 1e-12) shouldBe true
    Close(c.points.head, Vector2D(1 + 0.6 * 0.5, 1 + 0.8 * 0.5), 1e-12) shouldBe true
  }

  test("polygon-circle: circle against a face") {
    val b = box(1, 1, 0, 0)
    val c = circle(0.5, 0, 1.3)
    test(b, c) shouldBe true
    test(c, b) shouldBe true
    for collision <- Seq(collide(b, c), collide(c, b)) do
      collision shouldBe a[PolyCircleCollision]
      collision.shape1 shouldBe b // the polygon is the reference
      collision.shape2 shouldBe c
      Close(collision.normal, Vector2D(0, 1), 1e-12) shouldBe true
      Close(collision.points.head, Vector2D(0, 0.8), 1e-12) shouldBe true
  }

  test("polygon-circle: circle against a vertex") {
    val b = box(1, 1, 0, 0)
    val c = circle(0.5, 1.3, 1.3)
    test(b, c) shouldBe true
    val collision = collide(b, c)
    val n = Vector2D(1, 1).unit
    Close(collision.normal, n, 1e-12) shouldBe true
    Close(collision.points.head, Vector2D(1.3, 1.3) - n * 0.5, 1e-12) shouldBe true
    test(b, circle(0.5, 1.4, 1.4)) shouldBe false // 0.566 from the vertex
  }

  test("polygon-circle: centre inside the polygon, and separated") {
    val b = box(1, 1, 0, 0)
    val c = circle(0.2, 0.7, 0.1)
    test(b, c) shouldBe true
    val collision = collide(b, c)
    Close(collision.normal, Vector2D(1, 0), 1e-12) shouldBe true // nearest side: the right one
    Close(collision.points.head, Vector2D(0.5, 0.1), 1e-12) shouldBe true
    test(b, circle(0.05, 0, 0)) shouldBe true // deep inside, touching no side
    test(b, circle(0.5, 0, 1.6)) shouldBe false
  }

  test("polygon-circle: rotated polygon") {
    val b = box(1, 1, 0, 0, math.Pi / 4) // a diamond with a vertex at (0, sqrt 2)
    val c = circle(0.5, 0, math.sqrt(2) + 0.4)
    test(b, c) shouldBe true
    val collision = collide(b, c)
    Close(collision.normal, Vector2D(0, 1), 1e-12) shouldBe true // from the vertex to the centre
    Close(collision.points.head, Vector2D(0, math.sqrt(2) - 0.1), 1e-12) shouldBe true
  }

  test("polygon-polygon: overlapping boxes, reference chosen by the smallest overlap") {
    val first = box(1, 1, 0, 0)
    val second = box(1, 1, 1.5, 0.5)
    test(first, second) shouldBe true
    val collision = collide(first, second)
    collision shouldBe a[PolyCollision]
    // Overlap 0.5 on x, 1.5 on y; the second box's side normal (-1, 0) is found first.
    collision.shape1 shouldBe second
    collision.shape2 shouldBe first
    Close(collision.normal, Vector2D(-1, 0), 1e-12) shouldBe true
    collision.points.toList shouldBe List(Vector2D(1, 1), Vector2D(0.5, -0.5))
  }

  test("polygon-polygon: a rotated box with a vertex in the ground") {
    val ground = box(2, 0.5, 0, 0)
    val diamond = box(0.5, 0.5, 0, 0.5 + math.sqrt(0.5) - 0.05, math.Pi / 4)
    test(ground, diamond) shouldBe true
    val collision = collide(ground, diamond)
    collision.shape1 shouldBe ground
    Close(collision.normal, Vector2D(0, 1), 1e-12) shouldBe true
    collision.points.size shouldBe 1
    Close(collision.points.head, Vector2D(0, 0.45), 1e-12) shouldBe true
  }

  test("polygon-polygon: vertex against vertex") {
    val a = box(0.5, 0.5, 0, 0, math.Pi / 4)
    val b = box(0.5, 0.5, 1.4, 0, math.Pi / 4)
    test(a, b) shouldBe true
    val collision = collide(a, b)
    collision.normal.length shouldBe 1.0 +- 1e-12
    // All four axes overlap by the same 0.01 up to rounding: any diagonal, pointing away from shape1.
    math.abs(collision.normal.x) shouldBe math.sqrt(0.5) +- 1e-12
    (collision.normal dot (collision.shape2.pos - collision.shape1.pos)) should be > 0.0
    collision.points.toSet.map(p => (math.round(p.x * 1e9), math.round(p.y * 1e9))) shouldBe
      Set((math.round(math.sqrt(0.5) * 1e9), 0L), (math.round((1.4 - math.sqrt(0.5)) * 1e9), 0L))
  }

  test("polygon-polygon: separated and touching") {
    val a = box(1, 1, 0, 0)
    test(a, box(1, 1, 2.01, 0)) shouldBe false
    test(a, box(1, 1, 2, 0)) shouldBe true // touching counts
    test(a, box(0.5, 0.5, 2.1, 2.1, math.Pi / 4)) shouldBe false // AABBs overlap, shapes do not
  }

  test("regression: a box on a box gets a normal from the reference towards the incident box") {
    // The top and bottom sides tie on overlap; the side found first faces away from the
    // incident box when the lower box comes first. The normal must still point to shape2.
    for (lowerFirst, rotation) <- Seq((true, 0.0), (false, 0.0), (true, 0.01), (false, -0.01)) do
      val lower = box(0.3, 0.2, 0, 0.2)
      val upper = box(0.3, 0.2, 0.05, 0.595, rotation)
      val collision = if lowerFirst then collide(lower, upper) else collide(upper, lower)
      math.abs(collision.normal.y) shouldBe 1.0 +- 1e-3
      (collision.normal dot (collision.shape2.pos - collision.shape1.pos)) should be > 0.0
  }

  test("exactly touching boxes have no positive overlap on the touching axis (SiMS's rule, pinned)") {
    // Only positive overlaps count, so the side axis is chosen: a known weakness of the
    // original's rule, kept as specified; scenes start boxes a little apart.
    val collision = collide(box(0.5, 0.5, 0, 0.5), box(0.5, 0.5, 0, 1.5)) // both faces at y = 1 exactly
    math.abs(collision.normal.x) shouldBe 1.0 +- 1e-12
  }

  /** A box that is not a library Polygon: it gives only `vertices`, so the narrowphase reads it
    * through ConvexPolygon's default accessors.
    */
  private final class UserBox(halfWidth: Double, halfHeight: Double) extends Shape with ConvexPolygon:
    val density = 1.0
    def volume: Double = 4 * halfWidth * halfHeight
    def I: Double = mass * (4 * halfWidth * halfWidth + 4 * halfHeight * halfHeight) / 12
    def vertices: IndexedSeq[Vector2D] =
      IndexedSeq(Vector2D(halfWidth, halfHeight), Vector2D(-halfWidth, halfHeight),
        Vector2D(-halfWidth, -halfHeight), Vector2D(halfWidth, -halfHeight)).map(_.rotate(rotation) + pos)

  test("polygon-polygon: a user polygon collides like the library polygon of the same outline") {
    val user = UserBox(0.5, 0.25); user.pos = Vector2D(0.3, 0.6); user.asBody
    val twin = box(0.5, 0.25, 0.3, 0.6)
    val ground = box(2, 0.5, 0, 0)
    val expected = PolyCollision.referenceAxisIfColliding(twin, ground)
    expected should be >= 0
    PolyCollision.referenceAxisIfColliding(user, ground) shouldBe expected
    val fromUser = collide(user, ground)
    val fromTwin = collide(twin, ground)
    fromUser.normal.x shouldBe fromTwin.normal.x +- 1e-12
    fromUser.normal.y shouldBe fromTwin.normal.y +- 1e-12
    fromUser.points.size shouldBe fromTwin.points.size
    for (p, q) <- fromUser.points.zip(fromTwin.points) do
      p.x shouldBe q.x +- 1e-12
      p.y shouldBe q.y +- 1e-12
    PolyCollision.referenceAxisIfColliding(user, box(0.5, 0.5, 5, 5)) shouldBe -1 // far apart
  }
