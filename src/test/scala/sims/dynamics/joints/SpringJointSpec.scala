package sims.dynamics.joints

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.Generators
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D

class SpringJointSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private def momentum(bodies: Body*): Vector2D =
    bodies.map(b => b.linearVelocity * b.mass).reduce(_ + _)

  test("two free bodies on a damped spring keep their total momentum (no gravity)") {
    forAll(Generators.vector(3), Generators.vector(3), Gen.choose(0.0, 5.0), Gen.choose(1.0, 100.0),
      minSuccessful(20)) { (v1, v2, damping, k) =>
      val world = World()
      world.gravity = Vector2D.Null
      world.enableCollisionDetection = false
      val a = Circle(0.2, 1).asBody
      val b = Rectangle(0.3, 0.1, 2).asBody
      b.pos = Vector2D(1, 0.5)
      a.linearVelocity = v1
      b.linearVelocity = v2
      b.angularVelocity = 1
      world += a
      world += b
      val spring = SpringJoint(a, a.pos + Vector2D(0.1, 0), b, b.pos + Vector2D(0.2, 0), k)
      spring.damping = damping
      world += spring
      val p0 = momentum(a, b)
      for _ <- 1 to 300 do world.step()
      val p = momentum(a, b)
      val scale = math.max(1.0, p0.length)
      (p - p0).length should be < 1e-9 * scale
    }
  }

  test("Hooke's law: a stretched spring pulls the bodies together") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(1, 0)
    val spring = SpringJoint(a, b, 10)
    spring.initialLength shouldBe 1.0
    b.pos = Vector2D(1.5, 0)
    spring.force shouldBe Vector2D(5, 0) // on node1, towards node2
    spring.applyForce()
    a.force shouldBe Vector2D(5, 0)
    b.force shouldBe Vector2D(-5, 0)
  }

  test("damping opposes the relative motion, equal and opposite on both bodies") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(1, 0)
    val spring = SpringJoint(a, Vector2D(0, 0), b, Vector2D(1, 0), 0, 1)
    spring.damping = 2
    b.linearVelocity = Vector2D(3, 4) // separating at 3 m/s along the spring
    spring.applyForce()
    a.force shouldBe Vector2D(6, 0)
    b.force shouldBe Vector2D(-6, 0)
  }

  test("a damped spring oscillator loses energy, an undamped one keeps it roughly") {
    def run(damping: Double): Double =
      val world = World()
      world.gravity = Vector2D.Null
      world.enableCollisionDetection = false
      val anchor = Circle(0.1, 1).asBody
      anchor.fixed = true
      val particle = Circle(0.1, 1).asBody
      particle.pos = Vector2D(1, 0)
      world += anchor
      world += particle
      val spring = SpringJoint(anchor, particle, 20)
      spring.damping = damping
      world += spring
      particle.pos = Vector2D(1.3, 0)
      for _ <- 1 to 600 do world.step()
      val x = particle.pos.x - 1
      0.5 * particle.mass * (particle.linearVelocity dot particle.linearVelocity) + 0.5 * 20 * x * x
    val start = 0.5 * 20 * 0.09
    run(0) shouldBe start +- 0.2 * start
    run(0.5) should be < 0.1 * start
  }

  test("bad input is rejected") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(1, 0)
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(SpringJoint(a, a, 1)) should include("two different bodies")
    message(SpringJoint(a, b, -1)) should include("springConstant")
    message(SpringJoint(a, Vector2D(0, 0), b, Vector2D(1, 0), 1, -2)) should include("initialLength")
    message(SpringJoint(a, Vector2D(Double.NaN, 0), b, Vector2D(1, 0), 1)) should include("anchor1")
    message(SpringJoint(a, b, 1).damping = -1) should include("damping")
  }
