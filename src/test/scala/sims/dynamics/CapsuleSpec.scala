package sims.dynamics

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.geometry.{Projection, Vector2D}

/** The capsule's geometry and closed forms (its inertia against numeric integration is in
  * [[ShapeSpec]]).
  */
class CapsuleSpec extends AnyFunSuite with Matchers:

  test("area and inertia in closed form") {
    val c = Capsule(1, 0.5, 2)
    c.volume shouldBe 4 * 1 * 0.5 + math.Pi * 0.25
    // A capsule of half length 0 would be a disc: the formula then gives m r^2 / 2.
    val discLike = Capsule(1e-9, 1, 1)
    discLike.I shouldBe discLike.mass / 2 +- 1e-6
    c.mass shouldBe c.volume * 2
  }

  test("ends, bounds, projections and containment follow position and rotation") {
    val c = Capsule(1, 0.5, 1)
    c.pos = Vector2D(2, 1)
    c.vertex1 shouldBe Vector2D(1, 1)
    c.vertex2 shouldBe Vector2D(3, 1)
    c.AABB.minVertex shouldBe Vector2D(0.5, 0.5)
    c.AABB.maxVertex shouldBe Vector2D(3.5, 1.5)
    c.project(Vector2D(2, 0)) shouldBe Projection(Vector2D(2, 0), 1, 7) // units of the axis
    c.projectMin(0, 1) shouldBe 0.5
    c.projectMax(1, 0) shouldBe 3.5
    c.contains(Vector2D(3.4, 1.2)) shouldBe true // in the right cap
    c.contains(Vector2D(3.4, 1.4)) shouldBe false // outside the cap, inside the box
    c.rotation = math.Pi / 2
    c.vertex1.x shouldBe 2.0 +- 1e-12
    c.vertex1.y shouldBe 0.0 +- 1e-12
    c.maxY shouldBe 2.5 +- 1e-12
    c.contains(Vector2D(2.45, 1.9)) shouldBe true
    c.boundingRadius shouldBe 1.5
  }

  test("printed with its sizes and place; its core as a segment") {
    val c = Capsule(1, 0.5, 2)
    c.pos = Vector2D(1, 2)
    c.toString shouldBe s"Capsule(halfLength = ${1.0}, radius = 0.5, density = ${2.0}, pos = (${1.0}, ${2.0}))"
    c.core shouldBe sims.geometry.Segment(Vector2D(0, 2), Vector2D(2, 2))
  }

  test("bad sizes are rejected naming the argument") {
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(Capsule(0, 1, 1)) should include(s"halfLength must be positive and finite, got ${0.0}")
    message(Capsule(1, -1, 1)) should include("radius")
    message(Capsule(1, 1, Double.NaN)) should include("density")
  }
