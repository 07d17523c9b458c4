package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D
import sims.robustness.StateHash

/** A velocity of Double.MaxValue into a contact: finite, but the soft step carried
  * on with positions of 1.5e306 m where the classic step refuses it. Both now throw an
  * ArithmeticException naming the body and the stage, and leave the world as it was.
  */
class SoftStepOverflowSpec extends AnyFunSuite with Matchers:

  /** Two balls overlapping by 1 cm, no gravity; the first one's velocity is `velocity`. */
  private def pair(solver: Solver, velocity: Vector2D): (World, Body) =
    val world = World()
    world.gravity = Vector2D.Null
    world.solver = solver
    val a = Circle(0.5, 1)
    val b = Circle(0.5, 1)
    b.pos = Vector2D(0.99, 0)
    val ball = a.asBody
    world += ball
    world += b.asBody
    for _ <- 1 to 3 do world.step() // the soft step has its contacts by then
    ball.linearVelocity = velocity
    (world, ball)

  for (solver, stage) <- Seq((SoftStep(), "findContacts"), (ClassicStep, "velocity correction")) do
    val name = sims.dynamics.StepGuard.solverName(solver)
    test(s"$name: a velocity of Double.MaxValue into a contact throws, naming the body and '$stage', and restores the world") {
      val (world, ball) = pair(solver, Vector2D(Double.MaxValue, 0))
      val before = StateHash(world)
      val error = intercept[ArithmeticException](world.step())
      error.getMessage should include("body 0")
      error.getMessage should include(stage)
      error.getMessage should include("restored")
      StateHash(world) shouldBe before
      ball.linearVelocity = Vector2D(1, 0)
      world.step() // and the world goes on
      ball.pos.x should be > 0.0
    }

  test("SoftStep: an angular velocity of Double.MaxValue into a fixed wall names the spinning body") {
    val world = World()
    world.solver = SoftStep()
    val wall = Rectangle(2, 0.5, 1).asBody
    wall.fixed = true
    world += wall
    val box = Rectangle(0.25, 0.25, 1)
    box.pos = Vector2D(0, 0.74)
    val body = box.asBody
    world += body
    for _ <- 1 to 3 do world.step()
    body.angularVelocity = Double.MaxValue
    val before = StateHash(world)
    val error = intercept[ArithmeticException](world.step())
    error.getMessage should include("body 1")
    error.getMessage should include("findContacts")
    StateHash(world) shouldBe before
  }

  test("SoftStep: a speed whose square is finite (1e150 m/s, leaving a contact) still steps: the check is of overflow, not of size") {
    val (world, ball) = pair(SoftStep(), Vector2D(-1e150, 0))
    world.step()
    java.lang.Double.isFinite(ball.pos.x) shouldBe true
  }

  /** 3,000 balls in a row that collide with nothing, no gravity, under `workers` workers: only
    * the bodies' own stages see them (in ranges under two workers).
    */
  private def looseBalls(workers: Int): (World, IndexedSeq[Body]) =
    val world = World()
    world.gravity = Vector2D.Null
    world.solver = SoftStep(workers = workers)
    val bodies =
      for i <- 0 until 3000 yield
        val ball = Circle(0.1, 1)
        ball.collidable = false
        ball.pos = Vector2D(i * 0.3, 0)
        val body = ball.asBody
        world += body
        body
    (world, bodies)

  for workers <- Seq(1, 2) do
    test(
      s"SoftStep(workers = $workers): a position that overflows in the substeps fails the step at its end, naming the body, among 3,000 bodies") {
      // Bodies that collide with nothing, so that only the end of the step can see the overflow:
      // its finite check runs in ranges of bodies under two workers.
      val (world, bodies) = looseBalls(workers)
      world.step()
      bodies(2500).pos = Vector2D(1.79e308, 0)
      bodies(2500).linearVelocity = Vector2D(1e308, 0) // finite, but 1/60 s of it overflows the position
      val before = StateHash(world)
      val error = intercept[ArithmeticException](world.step())
      error.getMessage should include("body 2500")
      error.getMessage should include("soft step substeps")
      error.getMessage should include("restored")
      StateHash(world) shouldBe before
      bodies(2500).linearVelocity = Vector2D(-1, 0)
      world.step() // and the world goes on
      java.lang.Double.isFinite(bodies(2500).pos.x) shouldBe true
    }

  test(
    "SoftStep(workers = 2): a failed step restores what the step saved as it loaded the bodies: a body added since the last step, forces, a sleeper's rest, a fixed body moved") {
    val (world, bodies) = looseBalls(workers = 2)
    val post = Rectangle(0.1, 0.1, 1)
    post.pos = Vector2D(-5, 0)
    val fixed = post.asBody
    fixed.fixed = true
    world += fixed
    for _ <- 1 to 40 do world.step() // at rest: resting times grow
    fixed.pos = Vector2D(-5, 1) // sleepers on a fixed body the user moved wake at its next step
    val resting = bodies(7).sleepTime
    resting should be > 0.0
    val late = Circle(0.1, 1)
    late.collidable = false
    late.pos = Vector2D(0, 5)
    val added = late.asBody
    world += added // the saved state's arrays grow by one body
    added.linearVelocity = Vector2D(0.5, 0)
    bodies(12).applyForce(Vector2D(3, -2))
    bodies(2999).pos = Vector2D(1.79e308, 0)
    bodies(2999).linearVelocity = Vector2D(1e308, 0)
    val before = StateHash(world)
    val error = intercept[ArithmeticException](world.step())
    error.getMessage should include("body 2999")
    StateHash(world) shouldBe before
    added.linearVelocity shouldBe Vector2D(0.5, 0)
    bodies(12).force shouldBe Vector2D(3, -2)
    bodies(7).sleepTime shouldBe resting
    fixed.movedByUser shouldBe true
    bodies(2999).linearVelocity = Vector2D(-1, 0)
    world.step()
    fixed.movedByUser shouldBe false
  }
