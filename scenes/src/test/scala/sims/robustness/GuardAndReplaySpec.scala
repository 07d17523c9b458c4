package sims.robustness

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Circle, World}
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D
import sims.scenes.BallStack

class GuardAndReplaySpec extends AnyFunSuite with Matchers:

  test("a step that would make a velocity infinite throws, naming body and phase, and changes nothing") {
    val (world, balls) = BallStack.withBalls(10)
    for _ <- 1 to 30 do world.step()
    val before = StateHash(world)
    balls(3).applyForce(Vector2D(Double.MaxValue, 0)) // finite, but F / m overflows
    val error = intercept[ArithmeticException](world.step())
    error.getMessage should include("body 6") // 3 fixed bodies come first
    error.getMessage should include("velocity")
    error.getMessage should include("integration of accelerations")
    StateHash(world) shouldBe before
    balls(3).force.x shouldBe Double.MaxValue // forces are state too: restored as they were
    balls(3).force = Vector2D.Null
    world.step() // and the world goes on
  }

  test("a force whose sum with the forces already applied overflows is rejected where it is applied") {
    val (world, balls) = BallStack.withBalls(3)
    balls(0).applyForce(Vector2D(Double.MaxValue, 0))
    val before = StateHash(world)
    val error = intercept[IllegalArgumentException](balls(0).applyForce(Vector2D(Double.MaxValue, 0)))
    error.getMessage should include(s"total force (Infinity, ${0.0})")
    balls(0).force shouldBe Vector2D(Double.MaxValue, 0) // unchanged by the rejected call
    StateHash(world) shouldBe before
  }

  test("an absurd velocity that overflows positions is caught in the position phase") {
    val world = World()
    val ball = Circle(1, 1).asBody
    world += ball
    ball.linearVelocity = Vector2D(Double.MaxValue, 0)
    ball.pos = Vector2D(Double.MaxValue, 0)
    val before = StateHash(world)
    val error = intercept[ArithmeticException](world.step())
    error.getMessage should include("integration of velocities")
    StateHash(world) shouldBe before
  }

  test("restoring a snapshot and stepping again replays the run bit for bit") {
    val (world, _) = BallStack.withBalls(30)
    for _ <- 1 to 60 do world.step()
    val state = world.snapshot()
    state.timeOfState shouldBe world.time
    for _ <- 1 to 200 do world.step()
    val first = StateHash(world)
    world.restore(state)
    world.time shouldBe state.timeOfState
    for _ <- 1 to 200 do world.step()
    StateHash(world) shouldBe first
  }

  test("a snapshot cannot be restored into a world with other bodies") {
    val (world, _) = BallStack.withBalls(3)
    val state = world.snapshot()
    world += Circle(1, 1).asBody
    intercept[IllegalArgumentException](world.restore(state)).getMessage should include("other bodies")
  }

  test("joints keep working after a restore") {
    val world = World()
    val a = Circle(0.1, 1).asBody
    a.fixed = true
    val b = Circle(0.1, 1).asBody
    b.pos = Vector2D(1, 0)
    world += a
    world += b
    world += DistanceJoint(a, a.pos, b, b.pos)
    val state = world.snapshot()
    for _ <- 1 to 100 do world.step()
    val first = StateHash(world)
    world.restore(state)
    for _ <- 1 to 100 do world.step()
    StateHash(world) shouldBe first
  }
