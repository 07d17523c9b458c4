package sims.dynamics

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.{Close, Generators}
import sims.geometry.Vector2D

class BodySpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  /** A body of a circle at (0, 0) (mass pi) and a 2x2 square at (2, 0) (mass 4), the square turned. */
  private def composite(): Body =
    val c = Circle(1, 1)
    val r = Rectangle(1, 1, 1)
    r.pos = Vector2D(2, 0)
    r.rotation = 0.3
    Body(c, r)

  test("centre of mass, mass and parallel-axis inertia of a composite body") {
    val b = composite()
    val mc = math.Pi
    val mr = 4.0
    b.mass shouldBe mc + mr +- 1e-12
    b.pos.x shouldBe 2 * mr / (mc + mr) +- 1e-12
    b.pos.y shouldBe 0.0
    val dc = b.pos.x
    val dr = 2 - b.pos.x
    b.I shouldBe
      (mc / 2 + mc * dc * dc + mr * 8 / 12 + mr * dr * dr) +- 1e-12
    b.rotation shouldBe 0.0 // whatever the shapes' rotations
    b.shapes.map(_.body).distinct shouldBe Seq(b)
  }

  test("setting pos and rotation keeps the body rigid") {
    forAll(Generators.vector(50), Generators.angle, Generators.angle) { (p, a1, a2) =>
      val b = composite()
      val s0 = b.shapes.map(_.pos)
      val d0 = (s0(1) - s0(0)).length
      val relative0 = b.shapes(1).rotation - b.shapes(0).rotation
      b.rotation = a1
      b.pos = p
      b.rotation = a2
      Close(b.pos, p, 1e-9) shouldBe true
      b.rotation shouldBe a2
      (b.shapes(1).pos - b.shapes(0).pos).length shouldBe d0 +- 1e-9
      (b.shapes(1).rotation - b.shapes(0).rotation) shouldBe relative0 +- 1e-9
      // The centre of mass of the shapes is still the body's position.
      val com = b.shapes.map(s => s.pos * s.mass).reduce(_ + _) / b.shapes.map(_.mass).sum
      Close(com, p, 1e-9) shouldBe true
      // Each shape sits at its original offset rotated by the body's rotation.
      Close(b.shapes(1).pos - b.pos, (s0(1) - composite().pos).rotate(a2), 1e-9) shouldBe true
    }
  }

  test("rotation turns the shapes about the centre of mass") {
    val c1 = Circle(1, 1); c1.pos = Vector2D(-1, 0)
    val c2 = Circle(1, 1); c2.pos = Vector2D(1, 0)
    val b = Body(c1, c2)
    b.rotation = math.Pi / 2
    Close(c1.pos, Vector2D(0, -1), 1e-12) shouldBe true
    Close(c2.pos, Vector2D(0, 1), 1e-12) shouldBe true
    c2.rotation shouldBe math.Pi / 2
  }

  test("forces and impulses at points") {
    val b = Circle(1, 1).asBody
    b.applyForce(Vector2D(1, 0), Vector2D(0, 1))
    b.force shouldBe Vector2D(1, 0)
    b.torque shouldBe -1.0
    b.applyForce(Vector2D(0, 2))
    b.force shouldBe Vector2D(1, 2)
    b.applyImpulse(Vector2D(math.Pi, 0))
    b.linearVelocity.x shouldBe 1.0 +- 1e-12
    b.applyImpulse(Vector2D(0, math.Pi), Vector2D(1, 0))
    b.linearVelocity.y shouldBe 1.0 +- 1e-12
    b.angularVelocity shouldBe math.Pi / b.I +- 1e-12
    b.velocityOfPoint(Vector2D(1, 0)) shouldBe Vector2D(1, 1 + b.angularVelocity)
    b.velocityOfPoint(Vector2D(0, 1)) shouldBe Vector2D(1 - b.angularVelocity, 1)
    b.contains(Vector2D(0.5, 0.5)) shouldBe true
    b.contains(Vector2D(1, 1)) shouldBe false
  }

  test("mass and I follow fixed and kinematic both ways") {
    val b = Circle(0.5, 2).asBody
    val (m, i) = (b.mass, b.I)
    m shouldBe 2 * math.Pi * 0.25 +- 1e-12
    for (fixed, kinematic) <- Seq((true, false), (false, false), (false, true), (true, false), (false, true), (false, false)) do
      b.fixed = fixed
      b.kinematic = kinematic
      val immovable = fixed || kinematic
      withClue(s"fixed $fixed, kinematic $kinematic: ") {
        b.mass shouldBe (if immovable then Double.PositiveInfinity else m)
        b.I shouldBe (if immovable then Double.PositiveInfinity else i)
        b.invMass shouldBe (if immovable then 0.0 else 1 / m)
      }
  }

  test("a fixed body has infinite mass and ignores forces and impulses") {
    val b = Circle(1, 1).asBody
    b.linearVelocity = Vector2D(1, 1)
    b.angularVelocity = 1
    b.fixed = true
    b.linearVelocity shouldBe Vector2D.Null
    b.angularVelocity shouldBe 0.0
    b.mass shouldBe Double.PositiveInfinity
    b.I shouldBe Double.PositiveInfinity
    b.applyForce(Vector2D(1, 1))
    b.applyForce(Vector2D(1, 1), Vector2D(1, 0))
    b.applyImpulse(Vector2D(1, 1))
    b.applyImpulse(Vector2D(1, 1), Vector2D(0, 1))
    b.force shouldBe Vector2D.Null
    b.torque shouldBe 0.0
    b.linearVelocity shouldBe Vector2D.Null
    b.angularVelocity shouldBe 0.0
    b.fixed = false
    b.mass shouldBe math.Pi +- 1e-12
  }

  test("moving a shape of a body outside a world moves the centre of mass") {
    val c1 = Circle(1, 1)
    val c2 = Circle(1, 1); c2.pos = Vector2D(2, 0)
    val b = Body(c1, c2)
    b.pos shouldBe Vector2D(1, 0)
    c2.pos = Vector2D(4, 0)
    b.pos shouldBe Vector2D(2, 0)
    b.I shouldBe 2 * (c1.I + c1.mass * 4) +- 1e-9
  }

  test("bad input is rejected naming the argument") {
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(Body()) should include("at least one shape")
    val c = Circle(1, 1)
    message(Body(c, c)) should include("twice")
    c.asBody
    message(Body(c)) should include("already belongs to a body")
    val b = Circle(1, 1).asBody
    message(b.pos = Vector2D(Double.NaN, 0)) should include("pos")
    message(b.linearVelocity = Vector2D(0, Double.PositiveInfinity)) should include("linearVelocity")
    message(b.angularVelocity = Double.NaN) should include("angularVelocity")
    message(b.rotation = Double.NegativeInfinity) should include("rotation")
    message(b.force = Vector2D(Double.NaN, 1)) should include("force")
    message(b.torque = Double.NaN) should include("torque")
    message(b.applyForce(Vector2D(Double.NaN, 1))) should include("force")
    message(b.applyForce(Vector2D(1, 1), Vector2D(Double.NaN, 1))) should include("point")
    message(b.applyImpulse(Vector2D(Double.NaN, 1))) should include("impulse")
    message(b.applyImpulse(Vector2D(1, 1), Vector2D(Double.NaN, 1))) should include("point")
  }

  test("shapes of a body in a world cannot be moved") {
    val c = Circle(1, 1)
    val b = c.asBody
    val world = World()
    world += b
    intercept[IllegalArgumentException](c.pos = Vector2D(1, 1)).getMessage should include("already in a world")
    intercept[IllegalArgumentException](c.rotation = 1).getMessage should include("already in a world")
  }

  test("a force of 1e308 N applied 1e308 m away is rejected where it is given, naming its infinite torque") {
    val world = World()
    val b = Circle(1, 1).asBody
    world += b
    val error = intercept[IllegalArgumentException](b.applyForce(Vector2D(0, 1e308), Vector2D(1e308, 0)))
    error.getMessage should include("torque of Infinity")
    error.getMessage should include(s"(${1e308}, ${0.0})")
    b.force shouldBe Vector2D.Null
    b.torque shouldBe 0.0
    world.step() // nothing stuck: the next steps run
    world.step()
  }

  test("torques, forces and impulses whose sums overflow are rejected and change nothing") {
    val b = Circle(1, 1).asBody
    b.applyForce(Vector2D(0, 1e200), Vector2D(1e108, 0))
    intercept[IllegalArgumentException](b.applyForce(Vector2D(0, 1e200), Vector2D(1e108, 0))).getMessage should
      include("total torque Infinity")
    b.torque shouldBe 1e308
    b.force shouldBe Vector2D(0, 1e200)
    b.applyForce(Vector2D(0, Double.MaxValue))
    intercept[IllegalArgumentException](b.applyForce(Vector2D(0, Double.MaxValue))).getMessage should
      include(s"total force (${0.0}, Infinity)")
    val light = Circle(0.1, 1).asBody // 1 / mass = 32: an impulse of 1e308 N s overflows its speed
    intercept[IllegalArgumentException](light.applyImpulse(Vector2D(1e308, 0))).getMessage should include("velocities")
    light.linearVelocity shouldBe Vector2D.Null
    intercept[IllegalArgumentException](b.applyImpulse(Vector2D(0, 1e308), Vector2D(1e10, 0))).getMessage should
      include(s"at point (${1e10}, ${0.0})")
    b.linearVelocity shouldBe Vector2D.Null
    b.angularVelocity shouldBe 0.0
  }
