package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.dynamics.joints.{ForceJoint => ForceJointLike, Joint}
import sims.geometry.{AABB, Vector2D}
import sims.solver.{ClassicStep, SoftStep, Solver}

/** The world's one broadphase serves the steps and the queries: a query made in the middle of a
  * step, after the step filled the grid with its collidable shapes only (and its margins), still
  * sees every shape, sensors and shapes that do not collide included.
  */
class SharedBroadphaseSpec extends AnyFunSuite with Matchers:
  /** A joint of the user's own that asks the world which shapes are near, each time it is solved
    * and each time it applies its (zero) force: under the classic step that is before the
    * detector fills the grid (phase 2) and after (phase 4).
    */
  private final class Looking(val node1: Body, val node2: Body, probe: AABB) extends Joint with ForceJointLike:
    var seen = Vector.empty[Int]
    def applyForce(): Unit = seen :+= world.query(probe, sensors = true).size
    def correctVelocity(h: Double): Unit = seen :+= world.query(probe, sensors = true).size
    def correctPosition(h: Double): Unit = ()

  for solver <- Seq[Solver](ClassicStep, SoftStep()) do
    test(s"a query during a step under ${sims.dynamics.StepGuard.solverName(solver)} sees every shape") {
      val world = World()
      world.solver = solver
      val ground = Rectangle(5, 0.5, 1).asBody
      ground.fixed = true
      world += ground
      val ball = Circle(0.2, 1).asBody
      ball.pos = Vector2D(0, 0.7)
      world += ball
      val ghost = Circle(0.3, 1)
      ghost.collidable = false
      ghost.pos = Vector2D(3, 3)
      val zone = Rectangle(0.5, 0.5, 1)
      zone.sensor = true
      zone.pos = Vector2D(3.2, 3)
      val markers = Body(ghost, zone)
      markers.fixed = true
      world += markers
      val looking = Looking(ground, ball, AABB(Vector2D(2, 2), Vector2D(4, 4)))
      world += looking
      world.query(AABB(Vector2D(2, 2), Vector2D(4, 4)), sensors = true).size shouldBe 2
      for _ <- 1 to 3 do world.step()
      looking.seen.size should be >= 6
      looking.seen.distinct shouldBe Vector(2)
    }

  test("the detector's refresh after a soft step finds the collisions its own detect finds") {
    val world = World()
    world.solver = SoftStep()
    val ground = Rectangle(5, 0.5, 1).asBody
    ground.fixed = true
    world += ground
    for i <- 0 until 5 do
      val ball = Circle(0.2, 1).asBody
      ball.pos = Vector2D(-1 + 0.5 * i, 0.69)
      world += ball
    for _ <- 0 until 3 do world.step()
    // The soft step left its own candidate pairs in the world's broadphase.
    world.detector.refresh()
    def found = world.detector.collisions.map(c => (c.shape1.worldIndex, c.shape2.worldIndex)).sorted
    val refreshed = found
    world.detector.detect()
    refreshed shouldBe found
    refreshed.size shouldBe 5
  }
