package sims.solver

import java.lang.management.ManagementFactory
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, World}
import sims.dynamics.joints.{
  DistanceJoint, Joint, JointLimits, JointMotor, JointSpring, PrismaticJoint, RevoluteJoint, SpringJoint, WheelJoint
}
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

  test("joints with limits, motors and springs allocate nothing in the soft step's passes") {
    // A hanging chain of pins, each with a range and a motor, and a slider and a wheel with all
    // three: the passes solve these rows up to 12 times a step.
    val world = hanging(SoftStep(), 10, Vector2D(0.25, -0.05)) { (a, b) =>
      val pin = RevoluteJoint(a, b, (a.pos + b.pos) / 2)
      pin.limits = Some(JointLimits(-0.3, 0.3))
      pin.motor = Some(JointMotor(0.5, 2))
      pin
    }
    val base = Circle(0.2, 1).asBody
    base.fixed = true
    base.pos = Vector2D(-3, 0)
    val slider = Circle(0.2, 1).asBody
    slider.pos = Vector2D(-3, -1)
    val wheel = Circle(0.2, 1).asBody
    wheel.pos = Vector2D(-3, -2)
    Seq(base, slider, wheel).foreach(world += _)
    val slide = PrismaticJoint(base, base.pos, slider, slider.pos)
    slide.limits = Some(JointLimits(-0.5, 0.5))
    slide.motor = Some(JointMotor(0.2, 5))
    slide.spring = Some(JointSpring(2))
    val axle = WheelJoint(slider, wheel, wheel.pos, Vector2D(0, 1))
    axle.limits = Some(JointLimits(-0.2, 0.2))
    axle.motor = Some(JointMotor(3, 1))
    world += slide
    world += axle
    bytesPerStep(world, 1000) should be < 100.0
  }
