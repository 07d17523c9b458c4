package sims.dynamics

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.geometry.{Projection, Vector2D}

class ShapeSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  /** Area and polar moment about the shape's centre (per unit density) by sampling a grid. */
  private def integrate(shape: Shape, samples: Int): (Double, Double) =
    val box = shape.AABB
    val dx = (box.maxVertex.x - box.minVertex.x) / samples
    val dy = (box.maxVertex.y - box.minVertex.y) / samples
    var area, moment = 0.0
    for i <- 0 until samples; j <- 0 until samples do
      val p = Vector2D(box.minVertex.x + (i + 0.5) * dx, box.minVertex.y + (j + 0.5) * dy)
      if shape.contains(p) then
        area += dx * dy
        val r = p - shape.pos
        moment += (r dot r) * dx * dy
    (area, moment)

  private val shapes: Gen[Shape] = Gen.oneOf(
    Gen.choose(0.05, 5.0).map(r => Circle(r, 2)),
    for hw <- Gen.choose(0.05, 5.0); hh <- Gen.choose(0.05, 5.0) yield Rectangle(hw, hh, 2),
    for n <- Gen.choose(3, 12); r <- Gen.choose(0.05, 5.0) yield RegularPolygon(n, r, 2))

  /** Area within 1% and inertia within 1.5% of the numeric integrals, for shapes of `shapes`. */
  private def agreesWithIntegration(shapes: Gen[Shape]): Unit =
    forAll(shapes, Gen.choose(-1.0, 1.0), minSuccessful(30)) { (shape, rotation) =>
      shape.rotation = rotation
      shape.pos = Vector2D(3, -2)
      val (area, moment) = integrate(shape, 300)
      area shouldBe shape.volume +- 0.01 * shape.volume
      (moment * shape.density) shouldBe shape.I +- 0.015 * shape.I
      shape.mass shouldBe shape.volume * shape.density
    }

  test("mass and inertia formulas agree with numeric integration") {
    agreesWithIntegration(shapes)
  }

  test("mass and inertia of hulls agree with numeric integration") {
    agreesWithIntegration(HullPolygonSpec.hulls)
  }

  test("mass and inertia of capsules agree with numeric integration") {
    agreesWithIntegration(for hl <- Gen.choose(0.05, 5.0); r <- Gen.choose(0.05, 3.0) yield Capsule(hl, r, 2))
  }

  test("closed forms of the documentation") {
    val c = Circle(2, 3)
    c.volume shouldBe math.Pi * 4
    c.I shouldBe c.mass * 4 / 2
    val r = Rectangle(1, 2, 3)
    r.volume shouldBe 8.0
    r.I shouldBe r.mass * (4.0 + 16.0) / 12
    val square = RegularPolygon(4, 1, 1)
    square.volume shouldBe 2.0 +- 1e-12
    square.I shouldBe square.mass / 3 +- 1e-12 // side sqrt(2): m s^2 / 6
  }

  test("polygon area and inertia agree with the exact polygon formulas") {
    forAll(Gen.choose(3, 20), Gen.choose(0.1, 10.0)) { (n, radius) =>
      val p = RegularPolygon(n, radius, 1)
      val vs = p.vertices
      val pairs = vs.indices.map(i => (vs(i), vs((i + 1) % n)))
      val area = pairs.map((a, b) => a cross b).sum / 2
      // Polar moment of a polygon about the origin (its centre here).
      val moment = pairs.map((a, b) => (a cross b) * ((a dot a) + (a dot b) + (b dot b))).sum / 12
      p.volume shouldBe area +- 1e-9 * area
      p.I shouldBe moment +- 1e-9 * moment
    }
  }

  test("rectangle vertices go counter-clockwise from the upper right") {
    val r = Rectangle(2, 1, 1)
    r.vertices shouldBe IndexedSeq(Vector2D(2, 1), Vector2D(-2, 1), Vector2D(-2, -1), Vector2D(2, -1))
    r.pos = Vector2D(1, 1)
    r.vertices.head shouldBe Vector2D(3, 2)
    r.sides.map(_.n0) shouldBe IndexedSeq(Vector2D(0, 1), Vector2D(-1, 0), Vector2D(0, -1), Vector2D(1, 0))
  }

  test("regular polygon vertex i is (0, R) rotated by 2 pi i / n, then by the rotation") {
    val p = RegularPolygon(3, 2, 1)
    p.vertices(0) shouldBe Vector2D(0, 2)
    p.vertices(1).x shouldBe -2 * math.sin(2 * math.Pi / 3) +- 1e-12
    p.rotation = math.Pi / 2
    p.vertices(0).x shouldBe -2.0 +- 1e-12
    p.vertices(0).y shouldBe 0.0 +- 1e-12
  }

  test("projection, AABB and containment of shapes") {
    val c = Circle(1, 1)
    c.pos = Vector2D(2, 0)
    c.project(Vector2D(2, 0)) shouldBe Projection(Vector2D(2, 0), 2, 6) // in units of the axis
    c.AABB.minVertex shouldBe Vector2D(1, -1)
    c.contains(Vector2D(2.5, 0.5)) shouldBe true
    c.contains(Vector2D(3, 1)) shouldBe false
    val r = Rectangle(1, 1, 1)
    r.rotation = math.Pi / 4
    r.AABB.maxVertex.x shouldBe math.sqrt(2) +- 1e-12
    r.project(Vector2D.i).upper shouldBe math.sqrt(2) +- 1e-12
    r.contains(Vector2D(1.3, 0)) shouldBe true
    r.contains(Vector2D(1, 1)) shouldBe false
  }

  test("defaults of a shape") {
    val c = Circle(1, 1)
    c.restitution shouldBe 0.7
    c.friction shouldBe 0.707
    c.collidable shouldBe true
    c.transientShapes shouldBe empty
    c.body shouldBe null
    val b = c.asBody
    c.body shouldBe b
  }

  test("bad sizes, densities and coefficients are rejected naming the argument") {
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(Circle(0, 1)) should include("radius")
    message(Circle(-1, 1)) should include(s"${-1.0}")
    message(Circle(1, 0)) should include("density")
    message(Circle(Double.NaN, 1)) should include("radius")
    message(Circle(1, Double.PositiveInfinity)) should include("density")
    message(Rectangle(0, 1, 1)) should include("halfWidth")
    message(Rectangle(1, -2, 1)) should include("halfHeight")
    message(Rectangle(1, 1, -1)) should include("density")
    message(RegularPolygon(2, 1, 1)) should include("n must be at least 3, got 2")
    message(RegularPolygon(5, 0, 1)) should include("radius")
    message(RegularPolygon(5, 1, 0)) should include("density")
    message(Circle(1, 1).restitution = -0.1) should include("restitution")
    message(Circle(1, 1).friction = Double.NaN) should include("friction")
    message(Circle(1, 1).pos = Vector2D(Double.NaN, 0)) should include("pos")
    message(Circle(1, 1).rotation = Double.PositiveInfinity) should include("rotation")
  }
