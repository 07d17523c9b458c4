package sims.solver

import java.lang.management.ManagementFactory
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, World}
import sims.dynamics.joints.{DistanceJoint, Joint, SpringJoint}
import sims.geometry.Vector2D

/** A running world's step allocates (nearly) nothing: the checks it makes of every joint before
  * every step, and the broadphase's check of its settings, build no message, closure or boxed
  * number unless they fail, and a spring's force is computed without vectors.
  */
class StepAllocationSpec extends AnyFunSuite with Matchers:
  private val threads = ManagementFactory.getThreadMXBean.asInstanceOf[com.sun.management.ThreadMXBean]

  /** `links` balls hanging from a fixed ball, each `offset` below the last, each hung on the one
    * above by `link`.
    */
  private def hanging(solver: Solver, links: Int, offset: Vector2D)(link: (Body, Body) => Joint): World =
    val world = World()
    world.solver = solver
    val pivot = Circle(0.1, 1).asBody
    pivot.fixed = true
    world += pivot
    var last = pivot
    for i <- 1 to links do
      val ball = Circle(0.1, 1).asBody
      ball.pos = offset * i
      world += ball
      world += link(last, ball)
      last = ball
    world

  /** A chain of `links` balls on distance joints, hanging at rest. */
  private def chain(solver: Solver, links: Int): World =
    hanging(solver, links, Vector2D(0, -0.25))((a, b) => DistanceJoint(a, a.pos, b, b.pos))

  /** `links` balls on damped springs, bouncing. */
  private def springs(solver: Solver, links: Int): World =
    hanging(solver, links, Vector2D(0.05, -0.25)) { (a, b) =>
      val spring = SpringJoint(a, a.pos, b, b.pos, 20.0, 0.2)
      spring.damping = 0.01
      spring
    }

  private def bytesPerStep(world: World, steps: Int): Double =
    for _ <- 1 to 2000 do world.step() // let the JIT compile the step
    val before = threads.getCurrentThreadAllocatedBytes
    for _ <- 1 to steps do world.step()
    (threads.getCurrentThreadAllocatedBytes - before).toDouble / steps

  test("the classic step of a 100-link chain allocates under 100 bytes a step") {
    bytesPerStep(chain(ClassicStep, 100), 1000) should be < 100.0
  }

  test("the soft step of a 100-link chain allocates under 100 bytes a step") {
    bytesPerStep(chain(SoftStep(), 100), 1000) should be < 100.0
  }

  test("springs allocate nothing when they pull, under either step") {
    bytesPerStep(springs(ClassicStep, 20), 1000) should be < 100.0
    bytesPerStep(springs(SoftStep(), 20), 1000) should be < 100.0
  }
