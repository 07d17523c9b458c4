package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Capsule, Circle, Edge, HullPolygon, Rectangle, Shape, World}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, Solver, SoftStep}

/** Small simulations with capsules, edges and hulls under both steps: things come to rest on
  * an edge, lie flat, and roll down an edge slope.
  */
class RoundedSegmentSimulationSpec extends AnyFunSuite with Matchers:

  private val solvers: Seq[Solver] = Seq(ClassicStep, SoftStep())

  /** A world with an edge ground along y = 0 from x = -10 to 10 and the given shape dropped with
    * its centre at `at`, run for `seconds`.
    */
  private def dropped(solver: Solver, shape: Shape, at: Vector2D, seconds: Double = 3): Body =
    val world = World()
    world.solver = solver
    world += Edge(Vector2D(-10, 0), Vector2D(10, 0)).asBody
    shape.pos = at
    shape.restitution = 0
    val body = shape.asBody
    world += body
    for _ <- 1 to math.round(seconds / world.timeStep).toInt do world.step()
    body

  for solver <- solvers do
    test(s"$solver: a box comes to rest on an edge") {
      val box = dropped(solver, Rectangle(0.5, 0.25, 1), Vector2D(1, 1))
      box.pos.y shouldBe 0.25 +- 0.02
      box.pos.x shouldBe 1.0 +- 0.01
      box.rotation shouldBe 0.0 +- 0.01
      box.linearVelocity.length should be < 0.05
    }

    test(s"$solver: a capsule dropped at a slant comes to lie flat on an edge") {
      val pill = Capsule(0.6, 0.2, 1)
      pill.rotation = 0.3
      val body = dropped(solver, pill, Vector2D(0, 1))
      body.pos.y shouldBe 0.2 +- 0.02
      math.sin(pill.rotation) shouldBe 0.0 +- 0.02 // the shape's own rotation: lying flat
      body.angularVelocity shouldBe 0.0 +- 0.05
    }

    test(s"$solver: a hull and a capsule come to rest on a box") {
      val world = World()
      world.solver = solver
      val floor = Rectangle(3, 0.5, 1)
      floor.pos = Vector2D(0, -0.5)
      val ground = floor.asBody
      ground.fixed = true
      world += ground
      val hull = HullPolygon(Seq(Vector2D(-0.4, 0), Vector2D(0.4, 0), Vector2D(0.1, 0.6), Vector2D(-0.3, 0.5)), 1)
      hull.pos = hull.pos + Vector2D(-1, 0.2)
      val pill = Capsule(0.5, 0.15, 1)
      pill.pos = Vector2D(1, 0.5)
      world += hull.asBody
      world += pill.asBody
      for _ <- 1 to 180 do world.step()
      hull.body.linearVelocity.length should be < 0.05
      hull.body.shapes.head.AABB.minVertex.y shouldBe 0.0 +- 0.02
      pill.body.pos.y shouldBe 0.15 +- 0.02
    }

    test(s"$solver: a ball rolls down an edge slope as down a box's face of the same slope") {
      val angle = 0.3
      val down = Vector2D(math.cos(angle), -math.sin(angle))
      /** The ball's speed down the slope and its height over the slope's line after 1 s. */
      def roll(slope: Shape): (Double, Double) =
        val world = World()
        world.solver = solver
        val ground = slope.asBody
        ground.fixed = true
        world += ground
        val ball = Circle(0.25, 1)
        ball.pos = down * -5 + down.leftNormal * 0.25
        world += ball.asBody
        for _ <- 1 to 60 do world.step()
        (ball.body.linearVelocity dot down, ball.pos dot down.leftNormal)
      val plank = Rectangle(10, 0.5, 1)
      plank.rotation = -angle
      plank.pos = down.leftNormal * -0.5
      val (speed, height) = roll(Edge(down * -10, down * 10))
      val (plankSpeed, plankHeight) = roll(plank)
      speed shouldBe plankSpeed +- 1e-9
      height shouldBe plankHeight +- 1e-9
      speed should be > 0.9 * 9.81 * math.sin(angle) * 5 / 7 // rolling without slipping: 2.07 m/s
      height shouldBe 0.25 +- 0.005
    }
