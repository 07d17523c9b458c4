package sims.geometry

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalacheck.Gen
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.{Close, Generators}

class Vector2DSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  import Generators.*

  test("arithmetic on components") {
    val a = Vector2D(1, 2)
    val b = Vector2D(3, -5)
    a + b shouldBe Vector2D(4, -3)
    a - b shouldBe Vector2D(-2, 7)
    a * 2 shouldBe Vector2D(2, 4)
    b / 2 shouldBe Vector2D(1.5, -2.5)
    -a shouldBe Vector2D(-1, -2)
    (a dot b) shouldBe -7.0
    (a cross b) shouldBe (1.0 * -5 - 2.0 * 3)
    a.components shouldBe List(1.0, 2.0)
  }

  test("constants, normals and null") {
    Vector2D.Null.isNull shouldBe true
    Vector2D.i shouldBe Vector2D(1, 0)
    Vector2D.j shouldBe Vector2D(0, 1)
    Vector2D(2, 3).leftNormal shouldBe Vector2D(-3, 2)
    Vector2D(2, 3).rightNormal shouldBe Vector2D(3, -2)
    Vector2D(3, 4).length shouldBe 5.0
    Vector2D(3, 4).unit shouldBe Vector2D(0.6, 0.8)
    Vector2D(1e-3, 0).isNull shouldBe false
    Vector2D(1, Double.NaN).isFinite shouldBe false
    Vector2D(1, Double.PositiveInfinity).isFinite shouldBe false
    Vector2D(1, 2).toString shouldBe s"(${1.0}, ${2.0})"
  }

  test("unit of the null vector is an error") {
    val e = intercept[IllegalArgumentException](Vector2D.Null.unit)
    e.getMessage should include("null vector")
  }

  test("unit of a huge vector is not (0, 0): its length does not overflow") {
    val u = Vector2D(1e200, 1e200).unit
    u.x shouldBe math.sqrt(0.5) +- 1e-15
    u.y shouldBe u.x
    Vector2D(1e200, 1e200).length shouldBe math.sqrt(2) * 1e200 +- 1e185
    Vector2D(Double.MaxValue, 0).unit shouldBe Vector2D(1, 0)
  }

  test("unit of a tiny vector is no null-vector error: its length does not underflow") {
    Vector2D(1e-200, 0).unit shouldBe Vector2D(1, 0)
    Vector2D(0, -java.lang.Double.MIN_VALUE).unit shouldBe Vector2D(0, -1)
    Vector2D(3e-170, 4e-170).unit.x shouldBe 0.6 +- 1e-15
    Vector2D(3e-170, 4e-170).length shouldBe 5e-170 +- 1e-184
  }

  test("unit of a non-finite vector is an error naming it; its length is NaN or infinite") {
    intercept[IllegalArgumentException](Vector2D(Double.NaN, 1).unit).getMessage should include("NaN")
    intercept[IllegalArgumentException](Vector2D(Double.PositiveInfinity, 1).unit).getMessage should include("Infinity")
    Vector2D(Double.NaN, 1).length.isNaN shouldBe true
    Vector2D(Double.NegativeInfinity, 1).length shouldBe Double.PositiveInfinity
  }

  test("in the ordinary range, length and unit are the plain formulas, to the bit") {
    forAll(Gen.choose(-1e6, 1e6), Gen.choose(-1e6, 1e6)) { (x: Double, y: Double) =>
      whenever(x != 0 || y != 0) {
        val l = math.sqrt(x * x + y * y)
        Vector2D(x, y).length shouldBe l
        Vector2D(x, y).unit shouldBe Vector2D(x / l, y / l)
      }
    }
  }

  test("projection onto the null vector is the null vector") {
    Vector2D(1, 2).project(Vector2D.Null) shouldBe Vector2D.Null
    Vector2D(2, 3).project(Vector2D(2, 0)) shouldBe Vector2D(2, 0)
  }

  test("rotate preserves length and turns counter-clockwise") {
    Close(Vector2D.i.rotate(math.Pi / 2), Vector2D.j, 1e-15) shouldBe true
    forAll(vector(), angle) { (v, a) =>
      v.rotate(a).length shouldBe v.length +- 1e-9
      // The angle between v and its rotation is a: cross = |v|^2 sin a, dot = |v|^2 cos a.
      (v cross v.rotate(a)) shouldBe (v dot v) * math.sin(a) +- 1e-7
      (v dot v.rotate(a)) shouldBe (v dot v) * math.cos(a) +- 1e-7
    }
  }

  test("cross and dot identities") {
    forAll(vector(), vector(), vector()) { (a, b, c) =>
      (a cross b) shouldBe -(b cross a) +- 1e-9
      (a cross a) shouldBe 0.0
      (a dot b) shouldBe (b dot a)
      (a dot a.leftNormal) shouldBe 0.0 +- 1e-9
      (a cross b) shouldBe (a.leftNormal dot b) +- 1e-9
      (a cross b) shouldBe -(a.rightNormal dot b) +- 1e-9
      ((a + b) dot c) shouldBe ((a dot c) + (b dot c)) +- 1e-7
      // Lagrange identity in 2D: |a|^2 |b|^2 = (a.b)^2 + (a x b)^2.
      (a dot a) * (b dot b) shouldBe (math.pow(a dot b, 2) + math.pow(a cross b, 2)) +- 1e-3
    }
  }

  test("projection is parallel to the axis and leaves an orthogonal rest") {
    forAll(vector(), nonNullVector()) { (v, axis) =>
      val p = v.project(axis)
      (p cross axis) shouldBe 0.0 +- 1e-6 * (1 + v.length * axis.length)
      ((v - p) dot axis) shouldBe 0.0 +- 1e-6 * (1 + v.length * axis.length)
      p.project(axis).length shouldBe p.length +- 1e-9 * (1 + p.length)
    }
  }

  test("unit vectors have length 1 and keep the direction") {
    forAll(nonNullVector()) { v =>
      v.unit.length shouldBe 1.0 +- 1e-12
      (v.unit cross v) shouldBe 0.0 +- 1e-9
      (v.unit dot v) should be > 0.0
    }
  }
