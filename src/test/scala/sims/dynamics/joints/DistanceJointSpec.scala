package sims.dynamics.joints

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D

class DistanceJointSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private def pendulum(length: Double, startAngle: Double): (World, Body, DistanceJoint) =
    val world = World()
    world.enableCollisionDetection = false
    val pivot = Circle(0.05, 1).asBody
    pivot.fixed = true
    val bob = Circle(0.1, 1).asBody
    bob.pos = Vector2D(length * math.sin(startAngle), -length * math.cos(startAngle))
    world += pivot
    world += bob
    val rod = DistanceJoint(pivot, pivot.pos, bob, bob.pos)
    world += rod
    (world, bob, rod)

  test("a pendulum keeps its length within 1e-3 over 10 s") {
    forAll(Gen.choose(0.2, 3.0), Gen.choose(0.1, 3.0), minSuccessful(10)) { (length, angle) =>
      val (world, bob, rod) = pendulum(length, angle)
      var worst = 0.0
      for _ <- 1 to 600 do
        world.step()
        worst = math.max(worst, math.abs(bob.pos.length - length))
      worst should be < 1e-3
      rod.distance shouldBe length +- 1e-12
    }
  }

  test("the pendulum swings: it passes below the pivot") {
    val (world, bob, _) = pendulum(1, math.Pi / 2)
    var lowest = 0.0
    for _ <- 1 to 60 do
      world.step()
      lowest = math.min(lowest, bob.pos.y)
    lowest shouldBe -1.0 +- 0.01
  }

  test("connection points follow their bodies' motion and rotation") {
    val a = Rectangle(1, 0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(3, 0)
    val joint = DistanceJoint(a, Vector2D(1, 0), b, b.pos)
    a.rotation = math.Pi / 2
    joint.connection1.x shouldBe 0.0 +- 1e-12
    joint.connection1.y shouldBe 1.0 +- 1e-12
    a.pos = Vector2D(1, 1)
    joint.connection1.x shouldBe 1.0 +- 1e-12
    joint.connection1.y shouldBe 2.0 +- 1e-12
    joint.connection2 shouldBe Vector2D(3, 0)
    joint.x shouldBe Vector2D(3, 0) - joint.connection1
    joint.v shouldBe Vector2D.Null
  }

  test("position correction moves both bodies back to the distance, keeping their velocities") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(1, 0)
    val joint = DistanceJoint(a, a.pos, b, b.pos)
    b.pos = Vector2D(1.2, 0)
    b.linearVelocity = Vector2D(0, 1)
    joint.correctPosition(1.0 / 60)
    // Equal masses: each moves half of the error.
    a.pos.x shouldBe 0.1 +- 1e-12
    b.pos.x shouldBe 1.1 +- 1e-12
    b.linearVelocity shouldBe Vector2D(0, 1)
  }

  test("bad input is rejected") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(DistanceJoint(a, a.pos, a, Vector2D(1, 0))) should include("two different bodies")
    message(DistanceJoint(a, Vector2D(Double.NaN, 0), b, Vector2D(1, 0))) should include("anchor1")
    message(DistanceJoint(a, Vector2D(0, 0), b, Vector2D(0, Double.PositiveInfinity))) should include("anchor2")
    message(DistanceJoint(a, Vector2D(0, 0), b, Vector2D(0, 0))) should include("must differ")
    message(DistanceJoint(null, Vector2D(0, 0), b, Vector2D(0, 1))) should include("node1")
  }
