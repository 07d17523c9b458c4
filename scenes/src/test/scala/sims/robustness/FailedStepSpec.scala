package sims.robustness

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.collision.GridDetector
import sims.dynamics.{Circle, Rectangle, Shape, StepFailedException, World}
import sims.geometry.{AABB, Projection, Vector2D}
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Any exception inside `step()` leaves the world exactly as it was before the step and names
  * the stage that failed, under both solvers (once only an ArithmeticException rolled back).
  */
class FailedStepSpec extends AnyFunSuite with Matchers:

  /** A user's shape for which no narrowphase method exists until a test adds one. */
  final class Blob extends Shape:
    val density = 1.0
    val volume = 1.0
    val I = 1.0
    def AABB: AABB = new sims.geometry.AABB(pos - Vector2D(0.5, 0.5), pos + Vector2D(0.5, 0.5))
    def project(axis: Vector2D): Projection =
      Projection(axis, (pos dot axis) - 0.5 * axis.length, (pos dot axis) + 0.5 * axis.length)
    def contains(point: Vector2D): Boolean = (point - pos).length <= 0.5

  private val solvers: Seq[Solver] = Seq(ClassicStep, SoftStep())

  /** Balls on a floor after some steps (the soft step has a contact table by then), with a blob
    * dropped among them; `hook` is the world's post-step hook.
    */
  private def stackWithBlob(solver: Solver, hook: World => Unit = _ => ()): World =
    val world = new World() { override def postStep(): Unit = hook(this) }
    world.solver = solver
    val ground = Rectangle(3, 0.5, 1).asBody
    ground.pos = Vector2D(0, -0.5)
    ground.fixed = true
    world += ground
    for i <- 0 until 20 do
      val ball = Circle(0.2, 1)
      ball.pos = Vector2D(-1.5 + (i % 7) * 0.45 + (i / 7) * 0.1, 0.25 + (i / 7) * 0.45)
      world += ball.asBody
    for _ <- 1 to 30 do world.step()
    val blob = Blob()
    blob.pos = Vector2D(0, 0.9)
    world += blob.asBody
    world

  /** Fingerprint of the bodies' state (positions, velocities, forces) and the time. The soft
    * step's carried contacts are compared by replaying against a twin that never failed.
    */
  private def fingerprint(world: World): (Long, IndexedSeq[Vector2D], IndexedSeq[Double]) =
    (StateHash(world), world.bodies.map(_.force).toIndexedSeq, world.bodies.map(_.torque).toIndexedSeq)

  for solver <- solvers do
    val name = sims.dynamics.StepGuard.solverName(solver)

    test(s"$name: a pair no narrowphase method covers: IllegalStateException naming both shapes and the stage; nothing changed") {
      val world = stackWithBlob(solver)
      val before = fingerprint(world)
      val error = intercept[IllegalStateException](world.step())
      error.getMessage should include("Circle")
      error.getMessage should include("Blob")
      error.getMessage should include(if solver == ClassicStep then "stage 'velocity correction'" else "stage 'findContacts'")
      error.getCause shouldBe an[IllegalStateException]
      fingerprint(world) shouldBe before
    }

    test(s"$name: a user's detection method that throws: StepFailedException with the stage and the cause; nothing changed") {
      val world = stackWithBlob(solver)
      val detector = world.detector.asInstanceOf[GridDetector]
      detector.detectionMethods += { case (_: Circle, _: Blob) => throw UserBug("detection") }
      detector.detectionMethods += { case (_: Blob, _: Circle) => throw UserBug("detection") }
      val before = fingerprint(world)
      val error = intercept[StepFailedException](world.step())
      error.getCause shouldBe UserBug("detection")
      error.stage shouldBe (if solver == ClassicStep then "velocity correction" else "findContacts")
      error.getMessage should include("detection")
      fingerprint(world) shouldBe before
    }

    test(s"$name: a post-step hook that throws leaves the world as before the step, which then replays to the same bits") {
      var failOnce = false
      val failing = stackWithBlob(solver, _ => if failOnce then { failOnce = false; throw UserBug("hook") })
      val twin = stackWithBlob(solver)
      for w <- Seq(failing, twin) do
        val detector = w.detector.asInstanceOf[GridDetector]
        detector.detectionMethods += { case (_: Blob, _) | (_, _: Blob) => false } // the blob touches nothing
        for _ <- 1 to 20 do w.step()
      fingerprint(failing) shouldBe fingerprint(twin)
      val before = fingerprint(failing)
      failOnce = true
      val error = intercept[StepFailedException](failing.step())
      error.stage shouldBe "post-step hook"
      error.getMessage should include("post-step hook")
      fingerprint(failing) shouldBe before
      for _ <- 1 to 60 do { failing.step(); twin.step() }
      fingerprint(failing) shouldBe fingerprint(twin)
    }

    test(s"$name: the guard's ArithmeticException names the body whose speed overflowed, and the stage, and restores") {
      val world = stackWithBlob(solver)
      world -= world.bodies.last // no blob
      val before = StateHash(world)
      world.bodies(3).applyForce(Vector2D(Double.MaxValue, 0))
      val error = intercept[ArithmeticException](world.step())
      error.getMessage should include("non-finite")
      error.getMessage should include("body 3") // the ball pushed, not a body it touched
      error.getMessage should include(if solver == ClassicStep then "integration of accelerations" else "integrateVelocities")
      StateHash(world) shouldBe before
    }

/** A user's own exception type. */
final case class UserBug(where: String) extends RuntimeException(s"bug in $where")
