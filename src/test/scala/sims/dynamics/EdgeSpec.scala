package sims.dynamics

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.geometry.Vector2D

/** The edge: geometry of a segment with no thickness, no mass, only on fixed bodies. */
class EdgeSpec extends AnyFunSuite with Matchers:

  test("an edge lies between its two points, its centre in the middle") {
    val e = Edge(Vector2D(-1, 0), Vector2D(3, 4))
    e.pos shouldBe Vector2D(1, 2)
    e.rotation shouldBe math.atan2(4, 4)
    e.halfLength shouldBe math.sqrt(32) / 2
    e.vertex1.x shouldBe -1.0 +- 1e-12
    e.vertex2.y shouldBe 4.0 +- 1e-12
    e.AABB.minVertex.x shouldBe -1.0 +- 1e-12
    e.AABB.maxVertex.y shouldBe 4.0 +- 1e-12
    e.contains(Vector2D(0, 1.1)) shouldBe false
    // It contains the points of the segment, which rounding keeps exactly only on easy lines.
    val flat = Edge(Vector2D(-1, 0), Vector2D(3, 0))
    flat.contains(Vector2D(0.5, 0)) shouldBe true
    flat.contains(Vector2D(0.5, 1e-9)) shouldBe false
    e.radius shouldBe 0.0
    (e.volume, e.mass, e.I) shouldBe (0.0, 0.0, 0.0)
  }

  test("a body with an edge is fixed from the start and cannot be freed") {
    val ground = Edge(Vector2D(-5, 0), Vector2D(5, 0)).asBody
    ground.fixed shouldBe true
    ground.pos shouldBe Vector2D(0, 0)
    ground.mass shouldBe Double.PositiveInfinity
    intercept[IllegalArgumentException](ground.fixed = false).getMessage should
      (include("fixed must stay true") and include("got false"))
    // Edges with other shapes: the centre of mass is that of the shapes with mass.
    val ball = Circle(1, 1)
    ball.pos = Vector2D(2, 2)
    val mixed = Body(Edge(Vector2D(0, 0), Vector2D(1, 0)), ball)
    mixed.fixed shouldBe true
    mixed.pos shouldBe Vector2D(2, 2)
    // Edges alone: the middle of their centres.
    Body(Edge(Vector2D(0, 0), Vector2D(2, 0)), Edge(Vector2D(0, 2), Vector2D(2, 2))).pos shouldBe Vector2D(1, 1)
  }

  test("printed with its ends") {
    Edge(Vector2D(-1, 0), Vector2D(3, 0)).toString shouldBe s"Edge(from (${-1.0}, ${0.0}) to (${3.0}, ${0.0}))"
  }

  test("bad points are rejected naming the argument") {
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(Edge(Vector2D(1, 1), Vector2D(1, 1))) should include(s"end must differ from start, got (${1.0}, ${1.0})")
    message(Edge(Vector2D(Double.NaN, 1), Vector2D(1, 1))) should include("start must be finite")
    message(Edge(Vector2D(0, 0), null)) should include("end must not be null")
  }
