package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Circle, Rectangle}
import sims.geometry.Vector2D

/** A layout's SiMS world is the layout, body for body, with the materials the peers would give. */
class LayoutSpec extends AnyFunSuite with Matchers:
  private def body(outline: Outline, x: Double, fixed: Boolean = false, group: Int = 0) =
    SceneBody(outline, Vector2D(x, 1), fixed, if fixed then 0 else 2, friction = 0.5, restitution = 0.25, group)

  private val layout = Layout(
    IndexedSeq(body(Outline.Box(3, 0.5), 0, fixed = true), body(Outline.Circle(0.2), -1, group = 1),
      body(Outline.Circle(0.3), 1, group = 1), body(Outline.Box(0.2, 0.1), 2)),
    IndexedSeq(SceneJoint(1, 2)), Vector2D(0, -5), 0.01, Region(-3, 0, 3, 4))

  test("the world has the layout's bodies in order, fixed where the layout says, and its settings") {
    val world = layout.world()
    world.bodies.map(_.pos) shouldBe layout.bodies.map(_.centre)
    world.bodies.map(_.fixed) shouldBe Seq(true, false, false, false)
    world.gravity shouldBe Vector2D(0, -5)
    world.timeStep shouldBe 0.01
    world.bodies(1).shapes.head shouldBe a[Circle]
    world.bodies(3).shapes.head match
      case r: Rectangle => (r.halfWidth, r.halfHeight) shouldBe (0.2, 0.1)
      case other => fail(s"a box became $other")
    world.bodies(3).mass shouldBe 2 * 0.4 * 0.2 +- 1e-12
    layout.freeBodies shouldBe Seq(1, 2, 3)
  }

  test("a pair of SiMS shapes gets the pair values the peers give equal materials") {
    val shapes = layout.world().bodies.map(_.shapes.head)
    (shapes(0).friction * shapes(1).friction) shouldBe 0.5 +- 1e-15
    (shapes(0).restitution * shapes(1).restitution) shouldBe 0.25 +- 1e-15
  }

  test("bodies of one no-collide group never meet each other, and meet everything else") {
    val shapes = layout.world().bodies.map(_.shapes.head)
    shapes(1).transientShapes shouldBe Set(shapes(2))
    shapes(2).transientShapes shouldBe Set(shapes(1))
    shapes(0).transientShapes shouldBe empty
    shapes.forall(_.collidable) shouldBe true
  }

  test("a group of every body collides with nothing at all") {
    val chain = SwingingChain(5).layout.world()
    chain.bodies.flatMap(_.shapes).map(_.collidable).distinct shouldBe Seq(false)
  }

  test("joints hold the centres at their initial distance") {
    layout.length(SceneJoint(1, 2)) shouldBe 2.0
    val world = layout.world()
    world.joints.size shouldBe 1
  }

  test("a layout refuses joints to missing bodies, free bodies without density and negative groups") {
    an[IllegalArgumentException] should be thrownBy layout.copy(joints = IndexedSeq(SceneJoint(0, 4)))
    an[IllegalArgumentException] should be thrownBy layout.copy(joints = IndexedSeq(SceneJoint(2, 2)))
    an[IllegalArgumentException] should be thrownBy SceneBody(Outline.Circle(1), Vector2D.Null, false, 0, 0.5, 0)
    an[IllegalArgumentException] should be thrownBy SceneBody(Outline.Circle(1), Vector2D.Null, true, 0, 0.5, 0, -1)
  }

  test("a revolute joint pins the two bodies at the middle of their centres; a body starts at its velocity") {
    val pinned = layout.copy(
      bodies = layout.bodies.updated(3, layout.bodies(3).copy(velocity = Vector2D(40, -1))),
      joints = IndexedSeq(SceneJoint(1, 2, JointKind.Revolute), SceneJoint(2, 3)))
    pinned.pin(pinned.joints.head) shouldBe Vector2D(0, 1)
    val world = pinned.world()
    world.joints.map(_.getClass.getSimpleName) shouldBe Seq("RevoluteJoint", "DistanceJoint")
    world.joints.head match
      case pin: sims.dynamics.joints.RevoluteJoint =>
        pin.connection1 shouldBe Vector2D(0, 1)
        pin.connection2 shouldBe Vector2D(0, 1)
      case other => fail(s"the pin became $other")
    world.bodies(3).linearVelocity shouldBe Vector2D(40, -1)
    world.bodies(1).linearVelocity shouldBe Vector2D.Null
    an[IllegalArgumentException] should be thrownBy layout.bodies(0).copy(velocity = Vector2D(1, 0))
  }
