package sims.dynamics.joints

import org.scalacheck.{Gen, Shrink}
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D

class MouseJointSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  @annotation.nowarn("msg=unused") // taken by forAll as its Shrink[Double]: the lint misses that use
  private given Shrink[Double] = Shrink.shrinkAny

  private def world(gravity: Boolean): World =
    val w = World()
    w.enableCollisionDetection = false
    if !gravity then w.gravity = Vector2D.Null
    w

  /** A box of the given mass, 0.4 m by 0.2 m, at the origin. */
  private def box(mass: Double): Body = Rectangle(0.2, 0.1, mass / 0.08).asBody

  /** Drags `body` by `grab` to `target` for `seconds`; the largest distance from the target over
    * the last second and whether everything stayed finite.
    */
  private def drag(w: World, body: Body, grab: Vector2D, target: Vector2D, maxForce: Double,
      seconds: Double): (MouseJoint, Double) =
    w += body
    val mouse = MouseJoint(body, grab, maxForce)
    w += mouse
    mouse.target = target
    var lastSecond = 0.0
    while w.time < seconds do
      w.step()
      body.pos.isFinite shouldBe true
      if w.time > seconds - 1 then lastSecond = math.max(lastSecond, (mouse.connection - target).length)
    (mouse, lastSecond)

  private val masses = Gen.oneOf(Gen.const(0.01), Gen.const(1000.0), Gen.choose(-2.0, 3.0).map(math.pow(10, _)))

  test("a light or heavy body dragged without gravity reaches the target within 3 s and stays there") {
    forAll(masses, Gen.choose(-0.2, 0.2), minSuccessful(8)) { (mass, grabOffset) =>
      val w = world(gravity = false)
      val body = box(mass)
      val (_, distance) = drag(w, body, Vector2D(grabOffset, 0.05), Vector2D(2, 1), 1000 * mass, 4)
      info(f"mass $mass%.3g kg: distance from the target in the 4th second at most $distance%.1e m")
      // Pulled off its centre by up to 1000 g, the body spins; the damped spin still shakes the
      // grabbed point by a few millimetres after 3 s.
      distance should be < 0.01
    }
  }

  test("a light or heavy body held against gravity hangs at the target, sagging about g / omega^2") {
    forAll(masses, minSuccessful(8)) { mass =>
      val w = world(gravity = true)
      val body = box(mass)
      val (mouse, distance) = drag(w, body, Vector2D(0, 0), Vector2D(-1, 2), 1000 * mass, 4)
      val omega = 2 * math.Pi * mouse.frequency
      val sag = -w.gravity.y / (omega * omega)
      info(f"mass $mass%.3g kg: distance from the target in the 4th second at most $distance%.4f m, g / omega^2 = $sag%.4f m")
      distance should be < 1.5 * sag
      distance should be > 0.5 * sag
    }
  }

  test("the force on the body never exceeds maxForce") {
    forAll(masses, Gen.choose(0.1, 5.0), minSuccessful(8)) { (mass, accelerationBound) =>
      val w = world(gravity = false)
      val body = box(mass)
      w += body
      val maxForce = accelerationBound * mass
      val mouse = MouseJoint(body, Vector2D(0.1, 0), maxForce)
      w += mouse
      mouse.target = Vector2D(10, -5)
      var largest = 0.0
      for _ <- 1 to 240 do
        val momentum = body.linearVelocity * body.mass
        w.step()
        val force = (body.linearVelocity * body.mass - momentum).length / w.timeStep
        largest = math.max(largest, force)
        mouse.impulse.length should be <= maxForce * w.timeStep * (1 + 1e-12)
      largest should be <= maxForce * (1 + 1e-9)
      largest should be >= maxForce * (1 - 1e-9) // far from the target, the pull is the bound
    }
  }

  test("a force bound below the weight cannot lift the body") {
    val w = world(gravity = true)
    val body = box(2)
    val weight = body.mass * -w.gravity.y
    val (mouse, _) = drag(w, body, Vector2D(0, 0), Vector2D(0, 1), 0.5 * weight, 1)
    body.pos.y should be < -1.0 // falls with g / 2
  }

  test("a body follows a target moving on a circle, as in the viewer") {
    for mass <- Seq(0.01, 1.0, 1000.0) do
      val w = world(gravity = true)
      val body = box(mass)
      w += body
      val mouse = MouseJoint(body, Vector2D(0.15, 0.05), 1000 * mass)
      w += mouse
      var worst = 0.0
      for n <- 1 to 600 do
        val angle = n * w.timeStep
        mouse.target = Vector2D(math.cos(angle) - 1, math.sin(angle))
        w.step()
        if n > 120 then worst = math.max(worst, (mouse.connection - mouse.target).length)
      // Lag of a 5 Hz spring behind a target moving at 1 m/s, plus the sag under gravity.
      worst should be < 0.1
      body.linearVelocity.isFinite shouldBe true

  }

  test("node2 is the body; node1 is a fixed body at the target that no world needs") {
    val w = world(gravity = false)
    val body = box(1)
    w += body
    val mouse = MouseJoint(body, Vector2D(0.1, 0), 10)
    mouse.node2 should be theSameInstanceAs body
    mouse.node1.fixed shouldBe true
    mouse.node1.pos shouldBe Vector2D(0.1, 0)
    mouse.target shouldBe Vector2D(0.1, 0)
    mouse.target = Vector2D(3, 4)
    mouse.node1.pos shouldBe Vector2D(3, 4)
    w += mouse
    noException should be thrownBy w.step()
  }

  test("a body at rest at its target stays there") {
    val w = world(gravity = false)
    val body = box(1)
    w += body
    w += MouseJoint(body, Vector2D(0.1, 0.05), 10)
    for _ <- 1 to 60 do w.step()
    body.pos shouldBe Vector2D(0, 0)
    body.linearVelocity shouldBe Vector2D.Null
  }

  test("bad input is rejected with the argument's name") {
    val body = box(1)
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(MouseJoint(null, Vector2D(0, 0), 1)) should include("body")
    message(MouseJoint(body, Vector2D(Double.NaN, 0), 1)) should include("anchor")
    message(MouseJoint(body, Vector2D(0, 0), 0)) should include("maxForce")
    message(MouseJoint(body, Vector2D(0, 0), Double.NaN)) should include("maxForce")
    val mouse = MouseJoint(body, Vector2D(0, 0), 1)
    message(mouse.target = Vector2D(0, Double.PositiveInfinity)) should include("target")
    message(mouse.frequency = 0) should include("frequency")
    message(mouse.dampingRatio = -1) should include("dampingRatio")
    message(mouse.angularDamping = Double.NaN) should include("angularDamping")
  }

  test("stepping a world with a mouse joint whose body is not in it fails") {
    val w = world(gravity = false)
    w += Circle(0.1, 1).asBody
    w += MouseJoint(box(1), Vector2D(0, 0), 10)
    intercept[IllegalArgumentException](w.step()).getMessage should include("not in this world")
  }
