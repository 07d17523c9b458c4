package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Circle, Rectangle, World}
import sims.dynamics.joints.RevoluteJoint
import sims.geometry.Vector2D
import sims.io.WorldCodec

/** Bodies' ids and names, user data, and finding bodies again in a loaded world. */
class IdsAndNamesSpec extends AnyFunSuite with Matchers:
  test("bodies get ids 0, 1, 2 ... as they join, never given twice, and are found by id and name") {
    val world = World()
    val bodies = Seq.fill(3)(Circle(0.5).asBody)
    bodies.head.id shouldBe -1
    bodies.foreach(world += _)
    bodies.map(_.id) shouldBe Seq(0, 1, 2)
    world -= bodies(1)
    val later = Circle(0.5).asBody
    world += later
    later.id shouldBe 3
    world.bodyById(1) shouldBe None
    world.bodyById(3) shouldBe Some(later)
    world += bodies(1) // back with its own id
    bodies(1).id shouldBe 1
    world.bodyById(1) shouldBe Some(bodies(1))
    later.name = Some("player")
    world.bodyNamed("player") shouldBe Some(later)
    world.bodyNamed("nobody") shouldBe None
    later.toString should include("name = player")
  }

  test("a body joining with an id another body has gets the next one") {
    val first = World()
    val a = Circle(0.5).asBody
    first += a
    val second = World()
    val b = Circle(0.5).asBody
    second += b
    first -= a
    second += a
    a.id shouldBe 1
    second.bodyById(0) shouldBe Some(b)
  }

  test("save and load keep ids and names of bodies and joints, user data stays the user's") {
    val world = World()
    val ground = Rectangle(5, 0.5).asBody
    ground.fixed = true
    ground.name = Some("ground")
    world += ground
    val ball = Circle(0.3).asBody
    ball.pos = Vector2D(1, 2)
    ball.name = Some("ball")
    ball.userData = Some("mine")
    world += ball
    world -= ground
    world += ground // ids 1 and 0 now, in world order ball, ground
    val hinge = RevoluteJoint(ground, ball, Vector2D(0, 2))
    hinge.name = Some("hinge")
    world += hinge
    ball.shapes.head.userData = Some(42)
    hinge.userData = Some('x')
    ball.shapes.head.userData shouldBe Some(42)
    hinge.userData shouldBe Some('x')
    val loaded = WorldCodec.load(WorldCodec.save(world))
    loaded.bodies.map(_.id) shouldBe Seq(1, 0)
    loaded.bodyById(1).flatMap(_.name) shouldBe Some("ball")
    loaded.bodyNamed("ground").map(_.id) shouldBe Some(0)
    loaded.bodyNamed("ball").map(_.pos) shouldBe Some(Vector2D(1, 2))
    loaded.jointNamed("hinge").map(_.node2.name) shouldBe Some(Some("ball"))
    loaded.bodyNamed("ball").get.userData shouldBe None // not saved: it may be anything
    val next = Circle(0.1).asBody
    loaded += next
    next.id shouldBe 2
  }

  test("a name must not be null") {
    val body = Circle(0.5).asBody
    intercept[IllegalArgumentException](body.name = null).getMessage should include("name")
    intercept[IllegalArgumentException](body.name = Some(null)).getMessage should include("name")
  }
