package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.Shape
import sims.solver.{ClassicStep, SoftStep}

/** The Shapes scene under both steps: nothing sinks through the valley's edges. */
class ShapesSpec extends AnyFunSuite with Matchers:

  /** Height of the valley's outline at x. */
  private def outline(x: Double): Double =
    val pairs = Shapes.Outline.sliding(2).toSeq
    val Seq(a, b) = pairs.find(p => p(0).x <= x && x <= p(1).x).getOrElse(pairs.head): @unchecked
    a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)

  for solver <- Seq(ClassicStep, SoftStep()) do
    test(s"$solver: every shape stays above the valley's outline; settled, at most 2 cm into the floor") {
      val world = Shapes.build().world
      world.solver = solver
      val falling: Seq[Shape] = world.shapes.filter(!_.body.fixed)
      var deepest = 0.0
      for step <- 1 to 300 do
        world.step()
        for s <- falling do
          val x = s.pos.x
          s.pos.y should be > outline(x)
          // Landing at 7 m/s a corner goes one step's travel deep (12 cm) before it is pushed
          // out; in the last second, how far a shape's lowest point reaches below the floor.
          if step > 240 && s.AABB.minVertex.x >= -2.5 && s.AABB.maxVertex.x <= 2.5 then
            deepest = math.max(deepest, -s.AABB.minVertex.y)
      deepest should be < 0.02
    }
