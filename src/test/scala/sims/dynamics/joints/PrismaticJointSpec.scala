package sims.dynamics.joints

import org.scalacheck.{Gen, Shrink}
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D

class PrismaticJointSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  // Report failing cases as generated; shrunk densities or speeds near 0 say nothing more.
  @annotation.nowarn("msg=unused") // taken by forAll as its Shrink[Double]: the lint misses that use
  private given Shrink[Double] = Shrink.shrinkAny

  private def world(): World =
    val w = World()
    w.enableCollisionDetection = false
    w

  private def ground(): Body =
    val body = Rectangle(1, 0.1, 1).asBody
    body.fixed = true
    body

  test("a slider on a fixed 30-degree line accelerates at g sin(30 deg) and stays on the line") {
    forAll(Gen.choose(0.1, 100.0), Gen.choose(-1.0, 1.0), minSuccessful(5)) { (density, offset) =>
      val w = world()
      val rail = ground()
      val slope = math.toRadians(30)
      val direction = Vector2D(math.cos(slope), math.sin(slope))
      val slider = Rectangle(0.2, 0.1, density).asBody
      slider.pos = direction * 2
      w += rail
      w += slider
      // The sliding point is off the slider's centre, so the line constraint also has to hold
      // the slider's rotation through the angle constraint.
      val sliding = slider.pos + Vector2D(offset * 0.2, 0.1)
      val joint = PrismaticJoint(rail, sliding - direction * 2, slider, sliding)
      w += joint
      val g = -w.gravity.y
      var worstLine, worstAngle = 0.0
      val speeds = collection.mutable.ArrayBuffer.empty[Double]
      for _ <- 1 to 120 do
        w.step()
        speeds += (slider.linearVelocity dot joint.axis)
        worstLine = math.max(worstLine, joint.lineError)
        worstAngle = math.max(worstAngle, math.abs(joint.angleError))
      // Velocity along the line over the last second, a least-squares slope would be the same
      // for a constant acceleration: (v(2 s) - v(1 s)) / 1 s.
      val acceleration = -(speeds(119) - speeds(59)) / (60 * w.timeStep)
      val expected = g * math.sin(slope)
      info(
        f"density $density%.1f: acceleration $acceleration%.6f m/s^2, expected $expected%.6f (${(acceleration / expected - 1) * 100}%.2e %%), line error $worstLine%.1e m, angle error $worstAngle%.1e rad")
      acceleration shouldBe expected +- 0.01 * expected
      worstLine should be < 1e-9
      worstAngle should be < 1e-9
      joint.translation should be < 2.0 // slid down, towards anchor1
    }
  }

  test("a slider on a free, spinning carrier stays on the carrier's line and keeps its relative rotation") {
    forAll(Gen.choose(-6.0, 6.0), Gen.choose(-3.0, 3.0), minSuccessful(5)) { (spin, slide) =>
      val w = world()
      val carrier = Rectangle(1, 0.1, 1).asBody
      val slider = Circle(0.15, 3).asBody
      slider.pos = Vector2D(0.5, 0.3)
      w += carrier
      w += slider
      val joint = PrismaticJoint(carrier, Vector2D(-0.5, 0), slider, slider.pos)
      w += joint
      carrier.angularVelocity = spin
      slider.linearVelocity = joint.axis * slide
      var worstLine, worstAngle = 0.0
      for _ <- 1 to 300 do
        w.step()
        worstLine = math.max(worstLine, joint.lineError)
        worstAngle = math.max(worstAngle, math.abs(joint.angleError))
      worstLine should be < 1e-6
      worstAngle should be < 1e-6
      (slider.angularVelocity - carrier.angularVelocity) shouldBe 0.0 +- 1e-9
    }
  }

  test("one velocity correction leaves only sliding along the line") {
    val a = Rectangle(0.5, 0.2, 1).asBody
    val b = Rectangle(0.3, 0.3, 2).asBody
    b.pos = Vector2D(1, 0.5)
    val joint = PrismaticJoint(a, Vector2D(0.2, 0.1), b, b.pos + Vector2D(0.1, 0))
    a.linearVelocity = Vector2D(1, -2)
    a.angularVelocity = 3
    b.angularVelocity = -1
    b.linearVelocity = Vector2D(0.5, 4)
    joint.correctVelocity(1.0 / 60)
    (b.angularVelocity - a.angularVelocity) shouldBe 0.0 +- 1e-12
    // The sliding point moves relative to the line only along it: n . (relative velocity) = 0,
    // where the line's point under the sliding point moves with body 1.
    val c2 = joint.connection2
    val relative = b.velocityOfPoint(c2) - a.velocityOfPoint(c2)
    (relative cross joint.axis) shouldBe 0.0 +- 1e-12
  }

  test("position correction puts the slider back on the line and at the reference angle") {
    val rail = ground()
    val b = Rectangle(0.2, 0.2, 1).asBody
    b.pos = Vector2D(1, 1)
    val joint = PrismaticJoint(rail, Vector2D(0, 0), b, b.pos)
    b.pos = Vector2D(1.3, 0.8)
    b.rotation = 0.4
    val along = joint.translation
    for _ <- 1 to 10 do joint.correctPosition(1.0 / 60)
    joint.lineError should be < 1e-9
    math.abs(joint.angleError) should be < 1e-9
    rail.pos shouldBe Vector2D(0, 0)
    joint.translation shouldBe along +- 1e-9
  }

  test("the line's direction turns with body 1 and the reference angle is the relative rotation at creation") {
    val a = Rectangle(0.5, 0.2, 1).asBody
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(2, 0)
    b.rotation = 0.25
    val joint = PrismaticJoint(a, Vector2D(0, 0), b, Vector2D(1, 0))
    joint.referenceAngle shouldBe 0.25
    joint.axis shouldBe Vector2D(1, 0)
    a.rotation = math.Pi / 2
    joint.axis.x shouldBe 0.0 +- 1e-12
    joint.axis.y shouldBe 1.0 +- 1e-12
    joint.angleError shouldBe (-math.Pi / 2) +- 1e-12
  }

  test("bad input is rejected with the argument's name") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(PrismaticJoint(a, Vector2D(0, 0), a, Vector2D(1, 0))) should include("two different bodies")
    message(PrismaticJoint(a, Vector2D(Double.NaN, 0), b, Vector2D(1, 0))) should include("anchor1")
    message(PrismaticJoint(a, Vector2D(0, 0), b, Vector2D(Double.PositiveInfinity, 0))) should include("anchor2")
    message(PrismaticJoint(a, Vector2D(1, 1), b, Vector2D(1, 1))) should include("must differ")
    message(PrismaticJoint(null, Vector2D(0, 0), b, Vector2D(1, 0))) should include("node1")
  }

  test("stepping a world with a joint whose body is not in it fails") {
    val w = world()
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    w += b
    w += PrismaticJoint(a, Vector2D(0, 0), b, Vector2D(1, 0))
    intercept[IllegalArgumentException](w.step()).getMessage should include("not in this world")
  }
