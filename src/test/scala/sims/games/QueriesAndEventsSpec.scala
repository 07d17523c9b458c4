package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.collision.{ContactBegin, ContactEnd}
import sims.dynamics.{Body, Capsule, Circle, Rectangle, World}
import sims.geometry.{AABB, Vector2D}
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Shape casts, the exact overlap query, sensors in queries, and the contact events' helpers
  * and switches.
  */
class QueriesAndEventsSpec extends AnyFunSuite with Matchers:
  /** A ground (its top at y = 0), a box of side 1 centred at (3, 0.5), a sensor zone at (-3, 1). */
  private def scene(): (World, Body, Body, Body) =
    val world = World()
    val ground = Rectangle(10, 0.5).asBody
    ground.pos = Vector2D(0, -0.5)
    ground.fixed = true
    world += ground
    val box = Rectangle(0.5, 0.5).asBody
    box.pos = Vector2D(3, 0.5)
    world += box
    val zone = Circle(1).asBody
    zone.pos = Vector2D(-3, 1)
    zone.shapes.head.sensor = true
    zone.fixed = true
    world += zone
    (world, ground, box, zone)

  test("a circle cast sideways meets the box's side: fraction, point and normal") {
    val (world, _, box, _) = scene()
    val hit = world.castShape(Circle(0.25), Vector2D(0, 0.5), Vector2D(6, 0.5)).get
    hit.shape shouldBe box.shapes.head
    // The circle's edge reaches x = 2.5 when its centre is at 2.25: fraction 2.25 / 6.
    hit.fraction shouldBe (2.25 / 6) +- 1e-3
    hit.point.x shouldBe 2.5 +- 1e-3
    hit.point.y shouldBe 0.5 +- 1e-6
    hit.normal.x shouldBe -1.0 +- 1e-6
    hit.normal.y shouldBe 0.0 +- 1e-6
  }

  test("a box and a capsule cast down land on the ground; a cast that goes away misses") {
    val (world, ground, _, _) = scene()
    val boxHit = world.castShape(Rectangle(0.5, 0.25), Vector2D(0, 2), Vector2D(0, -2)).get
    boxHit.shape shouldBe ground.shapes.head
    boxHit.fraction shouldBe (1.75 / 4) +- 1e-3 // its bottom at 1.75 above the ground
    boxHit.point.y shouldBe 0.0 +- 1e-3
    boxHit.point.x shouldBe 0.0 +- 1e-6 // the middle of the side that lands
    boxHit.normal shouldBe Vector2D(0, 1)
    val capsule = Capsule(0.5, 0.2)
    capsule.rotation = math.Pi / 2 // standing up: its lower end 0.7 below its centre
    val capsuleHit = world.castShape(capsule, Vector2D(-6, 3), Vector2D(-6, -1)).get
    capsuleHit.fraction shouldBe (2.3 / 4) +- 1e-3
    capsuleHit.point.y shouldBe 0.0 +- 1e-3
    capsule.rotation shouldBe math.Pi / 2 // put back as it was
    world.castShape(Circle(0.2), Vector2D(0, 2), Vector2D(0, 5)) shouldBe None
  }

  test("a cast starting inside a shape hits it at fraction 0; casts skip sensors unless asked") {
    val (world, ground, _, zone) = scene()
    world.castShape(Circle(0.2), Vector2D(0, -0.1), Vector2D(0, 3)).map(h => (h.shape, h.fraction)) shouldBe
      Some((ground.shapes.head, 0.0))
    val across = world.castShape(Circle(0.2), Vector2D(-6, 1), Vector2D(0, 1))
    across shouldBe None
    world.castShape(Circle(0.2), Vector2D(-6, 1), Vector2D(0, 1), sensors = true).map(_.shape) shouldBe
      Some(zone.shapes.head)
    world.rayCast(Vector2D(-6, 1), Vector2D(0, 1)) shouldBe None
    world.rayCast(Vector2D(-6, 1), Vector2D(0, 1), sensors = true).map(_.shape) shouldBe Some(zone.shapes.head)
    world.shapesAt(Vector2D(-3, 1)) shouldBe empty
    world.shapesAt(Vector2D(-3, 1), sensors = true) shouldBe Seq(zone.shapes.head)
    world.query(AABB(Vector2D(-4, 0.5), Vector2D(-2, 1.5))) shouldBe empty
  }

  test("casts are refused for a shape of a body or of another kind") {
    val (world, _, box, _) = scene()
    intercept[IllegalArgumentException](world.castShape(box.shapes.head, Vector2D.Zero, Vector2D(1, 0)))
      .getMessage should include("body")
    val edge = sims.dynamics.Edge(Vector2D(0, 0), Vector2D(1, 0))
    intercept[IllegalArgumentException](world.castShape(null, Vector2D.Zero, Vector2D(1, 0))).getMessage should include("shape")
    intercept[IllegalArgumentException](world.castShape(Circle(1), Vector2D(Double.NaN, 0), Vector2D(1, 0)))
      .getMessage should include("from")
    edge.body shouldBe null
  }

  test("the overlap query is exact: a circle near a box's corner overlaps it only when it reaches it") {
    val (world, ground, box, _) = scene()
    val probe = Circle(0.3)
    // Its bounds overlap the box's near the corner (2.5, 1), but its centre is 0.35 m from it.
    probe.pos = Vector2D(2.5 - 0.247, 1 + 0.247)
    world.query(probe.AABB) should contain(box.shapes.head)
    world.overlapping(probe) shouldBe empty
    probe.pos = Vector2D(2.5 - 0.15, 1 + 0.15)
    world.overlapping(probe) shouldBe Seq(box.shapes.head)
    probe.pos = Vector2D(3, 0.1)
    world.overlapping(probe) shouldBe Seq(ground.shapes.head, box.shapes.head)
    world.overlapping(probe, _.body ne ground) shouldBe Seq(box.shapes.head)
    // A shape of the world: its own body's shapes are left out.
    world.overlapping(box.shapes.head) shouldBe empty // resting on the ground, touching only
  }

  test("contact events' helpers: involves and other") {
    val a = Circle(1)
    val b = Circle(1)
    val c = Circle(1)
    val begin = ContactBegin(a, b, Vector2D(1, 0), Vector2D.Zero, 1, 0)
    begin.involves(a) shouldBe true
    begin.involves(c) shouldBe false
    begin.other(a) shouldBe b
    begin.other(b) shouldBe a
    intercept[IllegalArgumentException](begin.other(c)).getMessage should include("not one of the pair")
    val end = ContactEnd(a, b)
    end.other(b) shouldBe a
    val body = a.asBody
    end.involves(body) shouldBe true
    end.involves(c.asBody) shouldBe false
  }

  /** A ball dropped on the ground under `solver`: the number of contact begins it makes. */
  private def drop(solver: Solver, world: World): Int =
    world.solver = solver
    val ground = Rectangle(5, 0.5).asBody
    ground.pos = Vector2D(0, -0.5)
    ground.fixed = true
    world += ground
    val ball = Circle(0.25).asBody
    ball.pos = Vector2D(0, 1)
    ball.shapes.head.restitution = 0 // one impact, one begin
    world += ball
    var begins = 0
    for _ <- 1 to 60 do
      world.step()
      begins += world.contactEvents.begins.length
    begins

  test("contact events can be switched off per world and per shape, the contacts solved all the same") {
    for solver <- Seq[Solver](ClassicStep, SoftStep()) do
      withClue(solver.toString) {
        drop(solver, World()) shouldBe 1
        val quiet = World()
        quiet.enableContactEvents = false
        drop(solver, quiet) shouldBe 0
        quiet.bodies(1).pos.y shouldBe 0.25 +- 0.02 // resting on the ground all the same
        quiet.contactEvents.touching shouldBe empty
        val muted = World()
        val begins = { muted.solver = solver; drop(solver, muted) }
        begins shouldBe 1
        muted.contactEvents.touching should have size 1
        muted.bodies(1).shapes.head.enableContactEvents = false
        muted.step()
        muted.contactEvents.ends should have size 1
        muted.contactEvents.touching shouldBe empty
        for _ <- 1 to 10 do muted.step()
        muted.contactEvents.begins shouldBe empty
      }
  }
