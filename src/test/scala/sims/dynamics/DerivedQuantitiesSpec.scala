package sims.dynamics

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.geometry.Vector2D

/** Sizes and densities that pass their own checks but whose mass or inertia over- or
  * underflows are rejected where the shape or body is made, naming its arguments.
  */
class DerivedQuantitiesSpec extends AnyFunSuite with Matchers:

  private def rejected(make: => Any): String = intercept[IllegalArgumentException](make).getMessage

  test("Circle(1e200, 1): its volume overflows, rejected naming radius and density") {
    val message = rejected(Circle(1e200, 1))
    message should include(s"Circle(radius = ${1e200}, density = ${1.0})")
    message should include("volume would be Infinity")
  }

  test("Rectangle(1e-300, 1e-300, 1): its volume underflows to 0, rejected naming its arguments") {
    val message = rejected(Rectangle(1e-300, 1e-300, 1))
    message should include(s"Rectangle(halfWidth = ${1e-300}, halfHeight = ${1e-300}, density = ${1.0})")
    message should include(s"volume would be ${0.0}")
  }

  test("Circle(1, 1e308): its mass overflows") {
    rejected(Circle(1, 1e308)) should include("mass would be Infinity")
  }

  test("Circle(1, 1e-320): its mass is subnormal and 1 / mass overflows") {
    rejected(Circle(1, 1e-320)) should include("mass would be 3.14")
  }

  test("Circle(1e150, 1): its moment of inertia overflows although its mass does not") {
    rejected(Circle(1e150, 1)) should include("moment of inertia would be Infinity")
    RegularPolygon(5, 1e150, 1e-300).mass should be > 0.0 // the same size with a light material is fine
  }

  test("RegularPolygon(3, 1e-170, 1): rejected naming n, radius and density") {
    rejected(RegularPolygon(3, 1e-170, 1)) should include(s"RegularPolygon(n = 3, radius = ${1e-170}, density = ${1.0})")
  }

  test("a body whose parts are fine but whose moment of inertia overflows is rejected, naming its shapes") {
    val a = Circle(1, 1e280)
    val b = Circle(1, 1e280)
    b.pos = Vector2D(1e20, 0)
    val message = rejected(Body(a, b))
    message should include("moment of inertia would be Infinity")
    message should include(s"Circle(radius = ${1.0}, density = ${1e280}")
  }

  test("moving a shape of a body so that the body's inertia overflows is rejected and leaves shape and body as they were") {
    val a = Circle(1, 1e280)
    val b = Circle(1, 1e280)
    b.pos = Vector2D(1, 0)
    val body = Body(a, b)
    val (centre, inertia) = (body.pos, body.I)
    rejected(b.pos = Vector2D(1e20, 0)) should include("moment of inertia")
    b.pos shouldBe Vector2D(1, 0)
    body.pos shouldBe centre
    body.I shouldBe inertia
  }

  test("a body's centre of mass is never NaN: far shapes whose moments overflow are rejected") {
    val a = Circle(1, 1e10)
    a.pos = Vector2D(1e300, 0)
    rejected(Body(a)) should include("centre of mass would be")
  }
