package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.World
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** The rain benchmark and its ragdoll: what the scene's description says, on a small rain. */
class RainSpec extends AnyFunSuite with Matchers:

  test("a human: eleven bones on ten joints, none of its own shapes colliding, the feet only with the ground") {
    val human = Human(Vector2D(0, 0), group = 3)
    human.bones.size shouldBe 11
    human.joints.size shouldBe 10
    val shapes = human.bones.flatMap(_.shapes)
    shapes.size shouldBe 13 // two feet
    shapes.map(_.groupIndex).distinct shouldBe Seq(-3)
    shapes.map(_.maskBits).count(_ == 1) shouldBe 2
    // The elbows start bent outside their limits, as in Box2D: angle -pi/4 below the lower -0.2 pi.
    human.joints.map(_.angle).count(a => math.abs(a + math.Pi / 4) < 1e-12) shouldBe 2
    human.bones.map(_.pos.y).max should be < 1.6
  }

  test("a human dropped on the ground lands whole: pins closed, joints within their limits") {
    val world = World()
    world.solver = SoftStep()
    world += Scene.ground(10)
    val human = Human(Vector2D(0, 2), group = 1)
    human.addTo(world)
    for _ <- 1 to 180 do world.step()
    all(human.joints.map(_.separation)) should be < 0.01
    for joint <- human.joints; limits <- joint.limits do
      joint.angle should (be >= limits.lower - 0.05 and be <= limits.upper + 0.05)
    all(human.bones.map(_.pos.y)) should be > 0.0
    all(human.bones.map(_.linearVelocity.length)) should be < 0.5
  }

  test("rain: a column every 8 steps until all are there, then the oldest dropped again; nothing falls through") {
    val rain = Rain(rows = 2, columns = 3, groupSize = 2)
    rain.name shouldBe "rain-2x3x2"
    BenchScenes.find("rain-2x3x2") shouldBe Some(rain)
    val world = rain.build().world.asInstanceOf[rain.RainWorld]
    world.bodies.size shouldBe 1
    world.bodies.head.shapes.size shouldBe 2 * 501
    world.step()
    world.columnCount shouldBe 1
    world.bodies.size shouldBe 1 + 2 * 2 * 11
    for _ <- 1 to 16 do world.step()
    world.columnCount shouldBe 3
    val bones = 1 + 3 * 2 * 2 * 11
    world.bodies.size shouldBe bones
    val first = world.groups(0)(0)
    for _ <- 1 to 8 do world.step()
    world.bodies.size shouldBe bones
    world.groups(0)(0) should not be first
    first.flatMap(_.bones).forall(_.world == null) shouldBe true
    // Dropped 40 m above its floor, a group lands after 2.9 s at 28 m/s: on the floor, not through it.
    for _ <- 1 to 240 do world.step()
    for column <- 0 until 3; row <- 0 until 2; human <- world.groups(column)(row); bone <- human.bones do
      bone.pos.y should be > row * Rain.FloorDistance
      bone.pos.y should be < row * Rain.FloorDistance + Rain.DropHeight + 2
  }
