package sims.dynamics

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.Generators
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

class WorldSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  test("defaults of a new world") {
    val world = World()
    world.timeStep shouldBe 1.0 / 60
    world.iterations shouldBe 10
    world.gravity shouldBe Vector2D(0, -9.81)
    world.enableCollisionDetection shouldBe true
    world.enablePositionCorrection shouldBe true
    world.time shouldBe 0.0
    world.bodies shouldBe empty
    world.detector shouldBe a[sims.collision.GridDetector]
  }

  test("free fall follows the closed form of semi-implicit Euler") {
    // v_n = v0 + n h a, x_n = x0 + n h v0 + h^2 a n (n + 1) / 2
    forAll(Generators.vector(5), Generators.vector(5), Gen.choose(1, 100)) { (x0, v0, n) =>
      whenever(v0.length > 0.01) {
        val world = World()
        val b = Circle(0.5, 2).asBody
        b.pos = x0
        b.linearVelocity = v0
        world += b
        for _ <- 1 to n do world.step()
        val h = world.timeStep
        val a = world.gravity
        val expected = x0 + v0 * (n * h) + a * (h * h * n * (n + 1) / 2)
        b.pos.x shouldBe expected.x +- 1e-12
        b.pos.y shouldBe expected.y +- 1e-12
        b.linearVelocity.y shouldBe (v0.y + n * h * a.y) +- 1e-12
        world.time shouldBe n * h +- 1e-12
      }
    }
  }

  test("speeds below the threshold become exactly zero before integrating positions") {
    val world = World()
    world.gravity = Vector2D.Null
    val b = Circle(1, 1).asBody
    b.linearVelocity = Vector2D(0.00006, 0.00006) // length 0.0000849
    b.angularVelocity = -0.00009
    world += b
    world.step()
    b.linearVelocity shouldBe Vector2D.Null
    b.angularVelocity shouldBe 0.0
    b.pos shouldBe Vector2D.Null
    b.rotation shouldBe 0.0
    b.linearVelocity = Vector2D(0.0002, 0)
    b.angularVelocity = 0.0002
    world.step()
    b.pos.x shouldBe 0.0002 * world.timeStep
    b.rotation shouldBe 0.0002 * world.timeStep
  }

  test("forces and torques act for one step and are reset") {
    val world = World()
    world.gravity = Vector2D.Null
    val b = Circle(1, 1).asBody
    world += b
    b.applyForce(Vector2D(b.mass, 0))
    b.torque = b.I
    world.step()
    b.linearVelocity.x shouldBe world.timeStep +- 1e-15
    b.angularVelocity shouldBe world.timeStep +- 1e-15
    b.force shouldBe Vector2D.Null
    b.torque shouldBe 0.0
    world.step()
    b.linearVelocity.x shouldBe world.timeStep +- 1e-15
  }

  test("a fixed body does not fall") {
    val world = World()
    val b = Rectangle(1, 1, 1).asBody
    b.fixed = true
    world += b
    for _ <- 1 to 10 do world.step()
    b.pos shouldBe Vector2D.Null
  }

  test("the post-step hook runs after every step") {
    var calls = 0
    val world = new World:
      override def postStep(): Unit = calls += 1
    world.step(); world.step()
    calls shouldBe 2
  }

  test("bodies and joints are added once and removed") {
    val world = World()
    val a = Circle(1, 1).asBody
    val b = Circle(1, 1).asBody
    b.pos = Vector2D(3, 0)
    world += a
    world += b
    world.shapes shouldBe a.shapes ++ b.shapes
    intercept[IllegalArgumentException](world += a).getMessage should include("already in this world")
    intercept[IllegalArgumentException](World() += a).getMessage should include("another world")
    val j = DistanceJoint(a, a.pos, b, b.pos)
    world += j
    intercept[IllegalArgumentException](world += j).getMessage should include("already in this world")
    world.joints shouldBe Seq(j)
    world -= j
    world.joints shouldBe empty
    world -= a
    world.bodies shouldBe Seq(b)
    world.shapes shouldBe b.shapes
    World() += a // free to join another world now
  }

  test("world.shapes is a snapshot: later additions and removals do not change it") {
    val world = World()
    val a = Body(Circle(1, 1), Circle(0.5, 1))
    val b = Circle(1, 1).asBody
    world += a
    val first = world.shapes
    world += b
    val second = world.shapes
    world -= a
    first shouldBe a.shapes
    second shouldBe a.shapes ++ b.shapes
    world.shapes shouldBe b.shapes
  }

  test("bodies removed and added back between two reads of the shapes are listed once, in join order") {
    val world = World()
    val bodies = IndexedSeq.fill(4)(Body(Circle(1, 1), Circle(0.5, 1)))
    bodies.foreach(world += _)
    world.shapes // read: the next changes start from a clean list
    world -= bodies(1)
    world -= bodies(2)
    world += bodies(1) // back, now the last to join
    world -= bodies(3)
    world.shapes shouldBe bodies(0).shapes ++ bodies(1).shapes
    world.shapes.map(_.worldIndex).distinct.size shouldBe 4
    // Removing a body that is not in this world changes nothing.
    val elsewhere = Circle(1, 1).asBody
    World() += elsewhere
    world -= elsewhere
    world -= bodies(2)
    world.bodies shouldBe Seq(bodies(0), bodies(1))
    elsewhere.index shouldBe 0
  }

  test("each body knows its index in the world's bodies, also after a removal") {
    val world = World()
    val bodies = Seq(Body(Circle(1, 1), Circle(0.5, 1)), Circle(1, 1).asBody, Body(Circle(1, 1), Circle(2, 1)))
    bodies.foreach(world += _)
    def indices = world.bodies.map(_.index)
    indices shouldBe Seq(0, 1, 2)
    world -= bodies(0)
    indices shouldBe Seq(0, 1)
    bodies(0).index shouldBe -1
    world += bodies(0)
    indices shouldBe Seq(0, 1, 2)
    world.bodies(2) should be theSameInstanceAs bodies(0)
  }

  test("a joint whose body is not in the world fails at step time") {
    val world = World()
    val a = Circle(1, 1).asBody
    val b = Circle(1, 1).asBody
    b.pos = Vector2D(3, 0)
    world += a
    world += DistanceJoint(a, a.pos, b, b.pos)
    intercept[IllegalArgumentException](world.step()).getMessage should include("not in this world")
  }

  test("bad settings are rejected naming the setting") {
    val world = World()
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(world.timeStep = 0) should include("timeStep")
    message(world.timeStep = Double.NaN) should include("timeStep")
    message(world.iterations = 0) should include("iterations must be at least 1, got 0")
    message(world.gravity = Vector2D(Double.NaN, 0)) should include("gravity")
  }

  test("a world made with another detector uses it (no grid detector is built)") {
    final class CountingDetector(val world: World) extends sims.collision.Detector:
      var detections = 0
      def collisions = IndexedSeq.empty
      def detect(): Unit = detections += 1
    val world = World(CountingDetector(_))
    world += Circle(1, 1).asBody
    world.step()
    world.detector shouldBe a[CountingDetector]
    // Once for the velocity iterations, then refresh() (by default detect()) in each position iteration.
    world.detector.asInstanceOf[CountingDetector].detections shouldBe 1 + world.iterations
    World().detector shouldBe a[sims.collision.GridDetector]
  }

  test("the solver can be switched, and must not be null") {
    val world = World()
    world.solver shouldBe sims.solver.ClassicStep
    intercept[IllegalArgumentException](world.solver = null).getMessage should include("solver")
  }
