package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Kinematic bodies, damping and gravity scale under both steps. */
class BodyFeaturesSpec extends AnyFunSuite with Matchers:
  private val solvers = Seq[Solver](ClassicStep, SoftStep())

  private def ground(world: World, halfWidth: Double = 20): Body =
    val g = Rectangle(halfWidth, 0.5).asBody
    g.pos = Vector2D(0, -0.5)
    g.fixed = true
    world += g
    g

  test("a kinematic body moves by its velocity alone: gravity, forces and contacts leave it") {
    for solver <- solvers do
      val world = World()
      world.solver = solver
      ground(world)
      val platform = Rectangle(1, 0.1).asBody
      platform.pos = Vector2D(0, 0.1) // resting on the ground: a fixed body cannot stop it
      platform.kinematic = true
      platform.linearVelocity = Vector2D(1, 0.5)
      platform.angularVelocity = 0.2
      world += platform
      for _ <- 1 to 60 do
        platform.applyForce(Vector2D(1000, 1000))
        world.step()
      withClue(solver.toString) {
        platform.linearVelocity shouldBe Vector2D(1, 0.5)
        platform.angularVelocity shouldBe 0.2
        platform.pos.x shouldBe 1.0 +- 1e-9
        platform.pos.y shouldBe 0.6 +- 1e-9
        platform.rotation shouldBe 0.2 +- 1e-9
        platform.mass shouldBe Double.PositiveInfinity
        platform.I shouldBe Double.PositiveInfinity
      }
  }

  test("a box resting on a kinematic platform is carried by friction, and pushed by a kinematic wall") {
    for solver <- solvers do
      val world = World()
      world.solver = solver
      world.gravity = Vector2D(0, -9.81)
      val platform = Rectangle(3, 0.1).asBody
      platform.pos = Vector2D(0, 0)
      platform.kinematic = true
      world += platform
      val box = Rectangle(0.25, 0.25).asBody
      box.pos = Vector2D(0, 0.35)
      box.shapes.head.friction = 1
      platform.shapes.head.friction = 1
      world += box
      for _ <- 1 to 30 do world.step() // settle
      platform.linearVelocity = Vector2D(1, 0)
      val startX = box.pos.x
      for _ <- 1 to 120 do world.step() // 2 s at 1 m/s
      withClue(s"$solver: box at ${box.pos}, platform at ${platform.pos}: ") {
        platform.pos.x shouldBe 2.0 +- 1e-6
        (box.pos.x - startX) shouldBe 2.0 +- 0.05
        box.pos.y shouldBe 0.35 +- 0.02
        box.linearVelocity.x shouldBe 1.0 +- 0.02
      }
  }

  test("a kinematic wall pushes a dynamic box out of its way and keeps its own speed") {
    val world = World()
    world.solver = SoftStep()
    ground(world)
    val box = Rectangle(0.25, 0.25).asBody
    box.pos = Vector2D(1, 0.25)
    world += box
    val wall = Rectangle(0.1, 1).asBody
    wall.pos = Vector2D(0, 1.2)
    wall.kinematic = true
    wall.linearVelocity = Vector2D(2, 0)
    world += wall
    for _ <- 1 to 60 do world.step()
    wall.linearVelocity shouldBe Vector2D(2, 0)
    box.pos.x should be > wall.pos.x + 0.1 + 0.25 - 0.02
    box.pos.x should be > 2.3
  }

  test("kinematic and fixed bodies pass through each other, as two kinematic bodies do") {
    val world = World()
    world.solver = SoftStep()
    ground(world)
    val a = Circle(0.5).asBody
    a.pos = Vector2D(-2, 0.2)
    a.kinematic = true
    a.linearVelocity = Vector2D(2, 0)
    val b = Circle(0.5).asBody
    b.pos = Vector2D(2, 0.2)
    b.kinematic = true
    b.linearVelocity = Vector2D(-2, 0)
    world += a
    world += b
    for _ <- 1 to 60 do world.step()
    a.pos.x shouldBe 0.0 +- 1e-9
    b.pos.x shouldBe 0.0 +- 1e-9
    world.contacts shouldBe empty
  }

  test("kinematic and fixed exclude each other; a body with an edge is never kinematic") {
    val body = Circle(1).asBody
    body.linearVelocity = Vector2D(1, 0)
    body.kinematic = true
    body.fixed shouldBe false
    body.linearVelocity shouldBe Vector2D(1, 0) // kept
    body.fixed = true
    body.kinematic shouldBe false
    body.linearVelocity shouldBe Vector2D.Zero
    body.kinematic = true
    body.fixed shouldBe false
    body.kinematic = false
    body.mass shouldBe body.shapes.head.mass
    val edge = sims.dynamics.Edge(Vector2D(0, 0), Vector2D(1, 0)).asBody
    val error = intercept[IllegalArgumentException](edge.kinematic = true)
    error.getMessage should include("kinematic")
  }

  test("linear and angular damping decay the velocities as 1 / (1 + h c) per step or substep") {
    for solver <- solvers do
      val world = World()
      world.solver = solver
      world.gravity = Vector2D.Zero
      val body = Circle(0.5).asBody
      body.linearVelocity = Vector2D(10, 0)
      body.angularVelocity = 4
      body.linearDamping = 1
      body.angularDamping = 2
      world += body
      for _ <- 1 to 60 do world.step()
      val parts = solver match
        case s: SoftStep => s.substeps
        case _ => 1
      val h = world.timeStep / parts
      withClue(solver.toString) {
        body.linearVelocity.x shouldBe 10 * math.pow(1 / (1 + h), 60.0 * parts) +- 1e-9
        body.angularVelocity shouldBe 4 * math.pow(1 / (1 + 2 * h), 60.0 * parts) +- 1e-9
        // About e^-1 and e^-2 of the start after one second.
        body.linearVelocity.x shouldBe 10 * math.exp(-1) +- 0.05
      }
  }

  test("gravity scale: 0 floats, -1 rises, 0.5 falls half as far") {
    for solver <- solvers do
      val world = World()
      world.solver = solver
      val bodies = Seq(0.0, -1.0, 0.5, 1.0).zipWithIndex.map { (scale, i) =>
        val b = Circle(0.1).asBody
        b.pos = Vector2D(i, 0)
        b.gravityScale = scale
        world += b
        b
      }
      for _ <- 1 to 60 do world.step()
      val drops = bodies.map(-_.pos.y)
      withClue(s"$solver: $drops") {
        drops(0) shouldBe 0.0
        drops(1) shouldBe -drops(3) +- 1e-9
        drops(2) shouldBe 0.5 * drops(3) +- 1e-9
        drops(3) shouldBe 4.9 +- 0.15
      }
  }

  test("bad damping and gravity scales are rejected naming the setting") {
    val body = Circle(1).asBody
    intercept[IllegalArgumentException](body.linearDamping = -1).getMessage should include("linearDamping")
    intercept[IllegalArgumentException](body.angularDamping = Double.NaN).getMessage should include("angularDamping")
    intercept[IllegalArgumentException](body.gravityScale = Double.PositiveInfinity).getMessage should include("gravityScale")
  }
