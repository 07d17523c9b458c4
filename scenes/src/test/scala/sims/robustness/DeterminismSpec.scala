package sims.robustness

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, World}
import sims.dynamics.joints.{DistanceJoint, SpringJoint}
import sims.geometry.Vector2D
import sims.scenes.Scene

/** Same inputs, same outputs, bit for bit. */
class DeterminismSpec extends AnyFunSuite with Matchers:

  /** A mixed scene; `allocationOrder` permutes the order in which the bodies are created
    * (and so their identity hash codes), never the order in which they join the world.
    */
  private def scene(allocationOrder: Seq[Int]): World =
    val world = World()
    val created = Array.ofDim[Body](12)
    for i <- allocationOrder do
      val shape = i % 3 match
        case 0 => Circle(0.2 + 0.01 * i, 1)
        case 1 => Rectangle(0.2, 0.15, 1)
        case _ => RegularPolygon(5, 0.25, 1)
      shape.pos = Vector2D(-1.5 + (i % 4) * 0.9 + 0.05 * (i / 4), 0.4 + (i / 4) * 0.7)
      created(i) = shape.asBody
    world += Scene.ground(3)
    created.foreach(world += _)
    world += DistanceJoint(created(0), created(0).pos, created(5), created(5).pos)
    world += SpringJoint(created(1), created(2), 30)
    world

  test("the same scene built twice gives bit-identical trajectories over 10,000 steps", sims.SlowTest) {
    val a = scene(0 until 12)
    val b = scene(0 until 12)
    for i <- 1 to 10000 do
      a.step()
      b.step()
      if i % 1000 == 0 then StateHash(a) shouldBe StateHash(b)
  }

  test("creating the bodies in another order (other identity hashes) changes nothing", sims.SlowTest) {
    val a = scene(0 until 12)
    val b = scene((0 until 12).reverse)
    val c = scene(Seq(5, 3, 11, 0, 7, 1, 9, 2, 10, 4, 8, 6))
    for i <- 1 to 10000 do
      a.step(); b.step(); c.step()
      if i % 1000 == 0 then
        StateHash(b) shouldBe StateHash(a)
        StateHash(c) shouldBe StateHash(a)
  }
