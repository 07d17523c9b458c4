package example.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.collision.Contact
import sims.dynamics.{CarriedState, Checked, Circle, World}
import sims.geometry.Vector2D
import sims.solver.Solver

/** The solver seam is public: a solver written outside the library, with its public API only,
  * advances time, names its stages, guards them, keeps per-world data carried from step to
  * step, and gets the world's transaction (a failed step changes nothing) and snapshots for free.
  */
class PublicSolverSpec extends AnyFunSuite with Matchers:
  import PublicSolverSpec.*

  private def fallingBall(): (World, sims.dynamics.Body) =
    val world = World()
    world.solver = ExplicitEuler
    val ball = Circle(0.5, 1).asBody
    ball.pos = Vector2D(0, 10)
    world += ball
    (world, ball)

  test("a solver of the user's own steps a world: time, positions and its per-world data") {
    val (world, ball) = fallingBall()
    for _ <- 1 to 3 do world.step()
    world.time shouldBe 3 * world.timeStep
    // Explicit Euler: x(n+1) = x(n) + h v(n), v(n+1) = v(n) + h g.
    val h = world.timeStep
    val g = world.gravity.y
    ball.pos.y shouldBe
      (10 + h * 0 + h * (h * g) + h * (2 * h * g)) +- 1e-12
    ball.linearVelocity.y shouldBe (3 * h * g) +- 1e-12
    world.workspace(classOf[Steps], Steps()).count shouldBe 3
  }

  test("its stage names the error of a failed step, and the world is restored") {
    val (world, ball) = fallingBall()
    world.step()
    ball.pos = Vector2D(0.999 * Double.MaxValue, 10)
    ball.linearVelocity = Vector2D(Double.MaxValue, 0) // its next position overflows
    val before = (world.time, ball.pos, ball.linearVelocity)
    val error = intercept[IllegalArgumentException](world.step())
    error.getMessage should include("stage 'integrate' of ExplicitEuler")
    (world.time, ball.pos, ball.linearVelocity) shouldBe before
    world.workspace(classOf[Steps], Steps()).count shouldBe 1 // its carried data put back too
    world.stage shouldBe "none"
  }

  test("its carried data is part of snapshots") {
    val (world, _) = fallingBall()
    world.step()
    val snapshot = world.snapshot()
    world.step()
    world.step()
    world.restore(snapshot)
    world.workspace(classOf[Steps], Steps()).count shouldBe 1
  }

  test("advanceTime and stage are for solvers, during a step") {
    val (world, _) = fallingBall()
    intercept[IllegalStateException](world.advanceTime()).getMessage should include("advanceTime is for a solver")
    intercept[IllegalStateException](world.stage = "mine").getMessage should include("stage is for a solver")
    world.guard("between steps", Checked.Positions) // a finite world passes the guard at any time
  }

object PublicSolverSpec:
  /** How many steps the solver made in a world: carried from step to step. */
  final class Steps extends CarriedState:
    var count = 0
    private var atStart = 0
    def copyState(): AnyRef = Integer.valueOf(count)
    def restoreState(saved: AnyRef): Unit = count = if saved == null then 0 else saved.asInstanceOf[Integer].intValue
    def beginStep(): Unit = atStart = count
    def undoStep(): Unit = count = atStart

  /** Explicit Euler without contacts: positions from the velocities at the start of the step. */
  object ExplicitEuler extends Solver:
    def step(world: World): Unit =
      val steps = world.workspace(classOf[Steps], Steps())
      steps.count += 1
      world.stage = "advance time"
      world.advanceTime()
      world.stage = "integrate"
      val h = world.timeStep
      for b <- world.bodies if !b.fixed do
        val v = b.linearVelocity
        b.pos = b.pos + v * h
        b.linearVelocity = v + world.gravity * h
      world.guard("integrate", Checked.Positions)

    def contacts(world: World): IndexedSeq[Contact] = IndexedSeq.empty
