package sims.robustness

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, World}
import sims.dynamics.joints.SpringJoint
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Random scenes, under both solvers: nothing a valid input does may produce an undocumented
  * error or a NaN.
  */
class FuzzSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  import RandomScenes.*

  private def kinetic(world: World): Double = world.bodies.filterNot(_.fixed).map(b =>
    0.5 * b.mass * (b.linearVelocity dot b.linearVelocity) + 0.5 * b.I * b.angularVelocity * b.angularVelocity).sum

  for solver <- Seq(ClassicStep, SoftStep()) do
    val name = sims.dynamics.StepGuard.solverName(solver)

    test(s"$name: random scenes with gravity, joints and springs run 2,000 steps without errors or NaN", sims.SlowTest) {
      forAll(sceneSpec, minSuccessful(8)) { spec =>
        val world = build(spec, gravity = true, springs = true, solver)
        for _ <- 1 to 2000 do world.step()
        finite(world) shouldBe true
      }
    }

    test(s"$name: in zero gravity, with restitution <= 1 and no springs, kinetic energy never rises above 105%", sims.SlowTest) {
      forAll(sceneSpec, minSuccessful(8)) { spec =>
        val world = build(spec, gravity = false, springs = false, solver)
        val start = kinetic(world)
        for _ <- 1 to 2000 do
          world.step()
          kinetic(world) should be <= 1.05 * start + 1e-9
        finite(world) shouldBe true
      }
    }

    test(s"$name: a spring too stiff for the time step (k = 1e12) is rejected where it is added, naming the limit") {
      val world = World()
      world.solver = solver
      val (a, b) = pair(world)
      val error = intercept[IllegalArgumentException](world += SpringJoint(a, b, 1e12))
      error.getMessage should include("too stiff for the time step")
      // The limit as this platform prints a Double ("4.0" on the JVM, "4" on Scala.js).
      error.getMessage should include(s"diverge from ${SpringJoint.StabilityLimit} on")
      SpringJoint.StabilityLimit shouldBe 4.0
      world.joints shouldBe empty
    }

    test(s"$name: a spring made too stiff by a longer time step fails the next step before anything changes") {
      val world = World()
      world.solver = solver
      val (a, b) = pair(world)
      world += SpringJoint(a, b, 0.1)
      for _ <- 1 to 10 do world.step()
      val before = (world.time, a.pos, b.pos, b.linearVelocity)
      world.timeStep = 1 // (k h^2) / m = 0.1 / (0.8 g / 2) = 255
      intercept[IllegalStateException](world.step()).getMessage should include("too stiff")
      (world.time, a.pos, b.pos, b.linearVelocity) shouldBe before
    }

    test(s"$name: a spring just inside the stability limit oscillates with bounded amplitude for 10,000 steps") {
      val world = World()
      world.solver = solver
      world.gravity = Vector2D.Null
      val (a, b) = pair(world)
      val h = solver.forceInterval(world)
      val k = 3.6 / (h * h * (a.invMassForTests + b.invMassForTests)) // stability number 3.6 of 4
      world += SpringJoint(a, b, k)
      b.linearVelocity = Vector2D(1, 0)
      var widest = 0.0
      for _ <- 1 to 10000 do
        world.step()
        widest = math.max(widest, math.abs(b.pos.x - a.pos.x))
      widest should be < 2.0 // starts 0.5 m apart; a diverging spring leaves every bound behind
    }

  /** Two light balls 0.5 m apart, in `world`. */
  private def pair(world: World): (Body, Body) =
    val a = Circle(0.05, 0.1).asBody // 0.8 g
    val b = Circle(0.05, 0.1).asBody
    b.pos = Vector2D(0.5, 0)
    world += a
    world += b
    (a, b)

  extension (body: Body) private def invMassForTests: Double = 1 / body.mass
