package sims.dynamics

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.geometry.Vector2D

/** The convex polygon made from any points: its hull, checks and mass properties (the
  * inertia against numeric integration is in [[ShapeSpec]]).
  */
class HullPolygonSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  test("the hull of a square with points inside and on its sides: four corners, counter-clockwise") {
    val points = Seq(Vector2D(2, 2), Vector2D(1, 1), Vector2D(0, 0), Vector2D(1, 0), Vector2D(2, 0), Vector2D(0, 2),
      Vector2D(0, 1), Vector2D(2, 2))
    val hull = HullPolygon(points, 3)
    hull.vertices shouldBe IndexedSeq(Vector2D(0, 0), Vector2D(2, 0), Vector2D(2, 2), Vector2D(0, 2))
    hull.pos shouldBe Vector2D(1, 1) // the centroid: the square stays where its points are
    hull.volume shouldBe 4.0
    hull.mass shouldBe 12.0
    hull.I shouldBe 12.0 * (4 + 4) / 12 +- 1e-12 // a 2 m square: m (a^2 + b^2) / 12
    hull.points shouldBe points
  }

  test("a triangle's centroid and inertia") {
    // Right triangle with legs 3 and 6: centroid (1, 2); about it, I = m (a^2 + b^2) / 18.
    val hull = HullPolygon(Seq(Vector2D(0, 0), Vector2D(3, 0), Vector2D(0, 6)), 1)
    hull.pos.x shouldBe 1.0 +- 1e-12
    hull.pos.y shouldBe 2.0 +- 1e-12
    hull.volume shouldBe 9.0 +- 1e-12
    hull.I shouldBe 9.0 * (9 + 36) / 18 +- 1e-9
  }

  test("a hull of a rectangle's corners has the rectangle's mass, inertia and contacts") {
    val corners = Seq(Vector2D(0.5, 0.25), Vector2D(-0.5, 0.25), Vector2D(-0.5, -0.25), Vector2D(0.5, -0.25))
    val hull = HullPolygon(corners, 2)
    val box = Rectangle(0.5, 0.25, 2)
    hull.mass shouldBe box.mass +- 1e-12
    hull.I shouldBe box.I +- 1e-12
    /** The contact's normal along y (its sign depends on the reference) and its points. */
    def contact(shape: Shape): (Double, Seq[(Double, Double)]) =
      shape.pos = Vector2D(0.1, 0.2) // its bottom 0.05 into the floor
      val floor = Rectangle(2, 0.5, 1)
      floor.pos = Vector2D(0, -0.5)
      val world = World()
      world += floor.asBody
      world += shape.asBody
      world.detector.detect()
      val c = world.collisions.head
      (math.abs(c.normal.y), c.points.toSeq.map(p => (math.rint(p.x * 1e9) / 1e9, math.rint(p.y * 1e9) / 1e9)).sorted)
    val expected = (1.0, Seq((-0.4, -0.05), (0.6, -0.05)))
    contact(hull) shouldBe expected
    contact(box) shouldBe expected
  }

  test("moved and turned like any polygon") {
    val hull = HullPolygon(Seq(Vector2D(0, 0), Vector2D(2, 0), Vector2D(0, 2), Vector2D(2, 2)), 1)
    hull.pos = Vector2D(5, 5)
    hull.rotation = math.Pi / 2
    hull.vertices.map(v => Vector2D(math.rint(v.x * 1e9) / 1e9, math.rint(v.y * 1e9) / 1e9)) shouldBe
      IndexedSeq(Vector2D(6, 4), Vector2D(6, 6), Vector2D(4, 6), Vector2D(4, 4))
    hull.contains(Vector2D(5.9, 5.9)) shouldBe true
  }

  test("printed with its corners, density and place") {
    HullPolygon(Seq(Vector2D(0, 0), Vector2D(2, 0), Vector2D(2, 2), Vector2D(0, 2)), 3).toString shouldBe
      s"HullPolygon(4 corners, density = ${3.0}, pos = (${1.0}, ${1.0}))"
  }

  test("bad points fail, naming the argument and the value") {
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0)), 1)) should include("points must hold at least 3 distinct points, got 2")
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(1, 0), Vector2D(0, 0)), 1)) should include("got 2")
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 1), Vector2D(3, 3)), 1)) should
      (include("points must not all lie on one line") and include(s"(${3.0}, ${3.0})"))
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(0.5, 1e-12)), 1)) should include("one line")
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(Double.NaN, 1)), 1)) should
      include(s"points must be finite, got (NaN, ${1.0}) at index 2")
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0), null), 1)) should include("at index 2")
    message(HullPolygon(null, 1)) should include("points must not be null")
    message(HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(0, 1)), 0)) should include("density")
  }

  test("property: every point lies in the hull, and the hull's corners are among the points") {
    forAll(Gen.listOfN(20, HullPolygonSpec.point)) { points =>
      whenever(points.distinct.size >= 3) {
        val hull = scala.util.Try(HullPolygon(points, 1)).toOption
        hull.foreach { h =>
          for p <- points do
            h.contains(p) || h.sides.exists(_.distance(p) < 1e-9) shouldBe true
          for v <- h.vertices do points.exists(p => (p - v).length < 1e-9) shouldBe true
          h.volume should be > 0.0
        }
      }
    }
  }

/** Generators of hulls, shared with [[ShapeSpec]]. */
object HullPolygonSpec:
  /** A point in a 10 m square about the origin. */
  val point: Gen[Vector2D] = for x <- Gen.choose(-5.0, 5.0); y <- Gen.choose(-5.0, 5.0) yield Vector2D(x, y)

  /** The hull of 3 to 12 random points around a circle of random size (never collinear). */
  val hulls: Gen[Shape] =
    for
      n <- Gen.choose(3, 12)
      radius <- Gen.choose(0.05, 5.0)
      angles <- Gen.listOfN(n, Gen.choose(0.0, 2 * math.Pi))
      inner <- Gen.listOfN(n, Gen.choose(0.3, 1.0))
    yield
      // A third point on each third of the circle keeps the points off one line.
      val spread = Seq(0.0, 2.1, 4.2).map(a => Vector2D(radius * math.cos(a), radius * math.sin(a)))
      HullPolygon(spread ++ angles.zip(inner).map((a, k) => Vector2D(k * radius * math.cos(a), k * radius * math.sin(a))), 2)
