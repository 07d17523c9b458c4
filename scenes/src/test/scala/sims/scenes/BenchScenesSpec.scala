package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The benchmark scenes: found by name, laid out as the Box2D v3 reference program lays them
  * out (the bench's `Dump` compares every number; these tests hold the shape of each layout).
  */
class BenchScenesSpec extends AnyFunSuite with Matchers:

  test("the standard scenes keep the bench's names and order") {
    BenchScenes.names shouldBe Seq("ballpit-500", "ballpit-1000", "ballpit-2000", "ballpit-4000", "ballpit-8000",
      "ballpit-16000", "pyramid-20", "chain-100", "ballstack", "large_pyramid", "many_pyramids", "joint_grid", "smash", "rain")
  }

  test("families are found by name for any size, ignoring case, and nothing else is") {
    BenchScenes.find("ballpit-123") shouldBe Some(Ballpit(123))
    BenchScenes.find("Pyramid-3") shouldBe Some(BoxPyramid(3))
    BenchScenes.find("chain-2") shouldBe Some(SwingingChain(2))
    BenchScenes.find("ballstack") shouldBe Some(BallStack)
    for name <- Seq("ballpit-0", "chain-1", "pyramid-", "pyramid-x", "ballpit-500x", "ballpit--5", "Chain") do
      withClue(name)(BenchScenes.find(name) shouldBe None)
    for name <- BenchScenes.names do Scenes.find(name).map(_.name.toLowerCase) shouldBe Some(name)
  }

  test("ballpit-N: a fixed floor and two walls, then N balls 45 to a row inside the walls") {
    val pit = Ballpit(500)
    val layout = pit.layout
    layout.bodies.size shouldBe 503
    layout.bodies.take(3).map(_.fixed) shouldBe Seq(true, true, true)
    layout.freeBodies shouldBe (3 until 503)
    val walls = layout.bodies.slice(1, 3).map(b =>
      b.outline match
        case Outline.Box(halfWidth, halfHeight) => (b.centre.x, halfWidth, b.centre.y - halfHeight, b.centre.y + halfHeight)
        case other => fail(s"a wall is $other"))
    walls.map(w => math.abs(w._1) - w._2) shouldBe Seq(5.0, 5.0) // inner faces at x = -5 and 5
    walls.map(_._3).foreach(_ shouldBe -1.0 +- 1e-12)
    walls.map(_._4).foreach(_ shouldBe pit.wallTop +- 1e-12)
    pit.wallTop shouldBe (0.12 + 11 * 0.22 + 0.1 + 1.0) +- 1e-12 // 12 rows
    for i <- layout.freeBodies do
      val ball = layout.bodies(i)
      val column = (i - 3) % 45
      ball.centre.x shouldBe (-4.84 + column * 0.22) +- 0.005
      layout.bounds.contains(ball.centre) shouldBe true
    layout.bounds shouldBe Region(-5, 0, 5, pit.wallTop)
  }

  test("the ball pit's shifts are drawn from its own seed: other sizes start with other shifts") {
    Ballpit(500).layout.bodies(3).centre should not equal Ballpit(1000).layout.bodies(3).centre
    Ballpit(500).layout shouldBe Ballpit(500).layout
  }

  test("pyramid-R: the ground and R rows of boxes, each row resting on the one below") {
    val layout = BoxPyramid(20).layout
    layout.bodies.size shouldBe 1 + 210
    layout.bodies.head.fixed shouldBe true
    layout.bodies.tail.map(_.centre.y).distinct shouldBe (0 until 20).map(0.25 + 0.5 * _)
    layout.bodies(1).centre.x shouldBe -19 * 0.5625 / 2
  }

  test("chain-N: N links on the x axis from the origin, the first fixed, joined neighbour to neighbour") {
    val layout = SwingingChain(100).layout
    layout.bodies.size shouldBe 100
    layout.bodies.map(_.fixed) shouldBe (true +: Seq.fill(99)(false))
    layout.bodies.map(_.noCollideGroup).distinct shouldBe Seq(1)
    layout.joints shouldBe (1 until 100).map(i => SceneJoint(i - 1, i))
    layout.joints.foreach(j => layout.length(j) shouldBe 0.2 +- 1e-12)
  }

  test("the quality scenes are found by name: stack-N, heavy-stack and drop-eE") {
    BenchScenes.find("stack-12") shouldBe Some(BoxStack(12))
    BenchScenes.find("Heavy-Stack") shouldBe Some(HeavyStack)
    BenchScenes.find("drop-e0.5") shouldBe Some(Drop(0.5))
    BenchScenes.find("drop-e1") shouldBe Some(Drop(1))
    BenchScenes.find("drop-e0") shouldBe Some(Drop(0))
    for name <- Seq("stack-0", "drop-e1.5", "drop-e", "drop-0.5", "drop-e.5") do
      withClue(name)(BenchScenes.find(name) shouldBe None)
    BenchScenes.quality.map(_.name) shouldBe Seq("pyramid-20", "stack-12", "chain-100", "ballpit-2000", "ballpit-4000",
      "heavy-stack", "drop-e1", "drop-e0.5", "drop-e0")
    for scene <- BenchScenes.quality do Scenes.find(scene.name) shouldBe Some(scene)
  }

  test("stack-N: the ground and N boxes of 0.5 m straight up, each on the one below, shifted by millimetres") {
    val layout = BoxStack(12).layout
    layout.bodies.size shouldBe 13
    layout.bodies.head.fixed shouldBe true
    val boxes = layout.bodies.tail
    boxes.map(_.outline).distinct shouldBe Seq(Outline.Box(0.25, 0.25))
    boxes.map(_.centre.y) shouldBe (0 until 12).map(0.25 + 0.5 * _)
    boxes.map(_.centre.x) shouldBe (0 until 12).map(i => 0.002 * ((i * 7) % 5 - 2))
    boxes.map(_.centre.x).distinct.size shouldBe 5
    boxes.map(b => (b.density, b.friction, b.restitution)).distinct shouldBe Seq((1.0, 0.5, 0.0))
  }

  test("heavy-stack: three boxes stacked as in stack-3, the top one 100 times denser") {
    val layout = HeavyStack.layout
    layout.bodies.map(_.centre) shouldBe BoxStack(3).layout.bodies.map(_.centre)
    layout.bodies.tail.map(_.density) shouldBe Seq(1.0, 1.0, 100.0)
    val world = HeavyStack.build().world
    world.bodies(3).mass shouldBe 100 * world.bodies(2).mass +- 1e-9
  }

  test("drop-eE: a ball 1 m above the ground, the pair's restitution E in SiMS as in the peers (max of equal values)") {
    for e <- Seq(0.0, 0.5, 1.0) do
      val layout = Drop(e).layout
      layout.bodies.map(_.restitution) shouldBe Seq(e, e)
      val ball = layout.bodies(1)
      ball.outline shouldBe Outline.Circle(Drop.Radius)
      ball.centre.y - Drop.Radius shouldBe 1.0
      val shapes = Drop(e).build().world.bodies.map(_.shapes.head)
      (shapes(0).restitution * shapes(1).restitution) shouldBe e +- 1e-15
  }

  test("every standard scene builds a SiMS world with the layout's bodies") {
    for case scene: LayoutScene <- BenchScenes.standard.filterNot(_.name == "ballpit-16000") do
      scene.build().world.bodies.size shouldBe scene.layout.bodies.size
  }

  test("Box2D's benchmark scenes and their smaller sizes are found by name") {
    BenchScenes.find("large_pyramid") shouldBe Some(LargePyramid(100))
    BenchScenes.find("Large_Pyramid-20") shouldBe Some(LargePyramid(20))
    BenchScenes.find("many_pyramids") shouldBe Some(ManyPyramids(20, 20))
    BenchScenes.find("many_pyramids-2x3") shouldBe Some(ManyPyramids(2, 3))
    BenchScenes.find("joint_grid") shouldBe Some(JointGrid(100))
    BenchScenes.find("joint_grid-10") shouldBe Some(JointGrid(10))
    BenchScenes.find("smash") shouldBe Some(Smash(120, 80))
    BenchScenes.find("smash-4x3") shouldBe Some(Smash(4, 3))
    for name <- Seq("large_pyramid-0", "joint_grid-6", "many_pyramids-0x3", "smash-3", "smash-3x0", "large_pyramid-") do
      withClue(name)(BenchScenes.find(name) shouldBe None)
  }

  test("large_pyramid: a 200 m ground box and 5,050 boxes of 1 m, side by side, each row centred on the one below") {
    val layout = LargePyramid().layout
    layout.bodies.size shouldBe 1 + 5050
    layout.bodies.head shouldBe SceneBody.box(sims.geometry.Vector2D(0, -1), 100, 1, fixed = true)
    val bottom = layout.bodies.slice(1, 101)
    bottom.map(_.centre.y).distinct shouldBe Seq(0.5)
    bottom.map(_.centre.x) shouldBe (0 until 100).map(j => -49.5 + j)
    val top = layout.bodies.last
    (top.centre.x, top.centre.y) shouldBe (0.0, 99.5)
    layout.bodies.tail.map(_.outline).distinct shouldBe Seq(Outline.Box(0.5, 0.5))
  }

  test("many_pyramids: 20 floors 11 m apart, each with 20 pyramids of 55 boxes standing on it") {
    val scene = ManyPyramids()
    val layout = scene.layout
    layout.bodies.count(_.fixed) shouldBe 20
    layout.freeBodies.size shouldBe 22000
    val floorTops = layout.bodies.filter(_.fixed).map(b =>
      b.outline match
        case Outline.Box(_, halfHeight) => b.centre.y + halfHeight
        case other => fail(s"a floor is $other"))
    floorTops.zipWithIndex.foreach((top, i) => top shouldBe (11.0 * i) +- 1e-12)
    scene.groundWidth shouldBe 220.0
    // The first pyramid's bottom row: x from -110 + 1 - 0.5 + 0.5, one box apart, resting on floor 0.
    val first = layout.bodies.slice(20, 30)
    first.map(_.centre) shouldBe (0 until 10).map(j => sims.geometry.Vector2D(-109.0 + j, 0.5))
    layout.freeBodies.map(i => layout.bodies(i).centre.x).max should be < 110.0
  }

  test("joint_grid: 100 x 100 discs that never collide, 19,800 pins, the top row's 7 middle discs fixed") {
    val grid = JointGrid()
    val layout = grid.layout
    layout.bodies.size shouldBe 10000
    layout.joints.size shouldBe 2 * 100 * 99
    layout.joints.map(_.kind).distinct shouldBe Seq(JointKind.Revolute)
    layout.bodies.indices.filter(layout.bodies(_).fixed) shouldBe (47 to 53).map(grid.index(_, 0))
    layout.bodies(grid.index(3, 7)).centre shouldBe sims.geometry.Vector2D(3, -7)
    layout.bodies.map(_.noCollideGroup).distinct shouldBe Seq(1)
    for j <- layout.joints do layout.length(j) shouldBe 1.0
    layout.world().bodies.flatMap(_.shapes).map(_.collidable).distinct shouldBe Seq(false)
  }

  test("smash: no gravity, an 8 m box at 40 m/s and a wall of 9,600 boxes of 0.4 m at rest") {
    val layout = Smash().layout
    layout.gravity shouldBe sims.geometry.Vector2D.Null
    layout.bodies.size shouldBe 1 + 9600
    layout.bodies.head.velocity shouldBe sims.geometry.Vector2D(40, 0)
    layout.bodies.head.density shouldBe 8.0
    layout.bodies.head.outline shouldBe Outline.Box(4, 4)
    layout.bodies.tail.map(_.velocity).distinct shouldBe Seq(sims.geometry.Vector2D.Null)
    layout.bodies(1).centre shouldBe sims.geometry.Vector2D(30, -16)
    layout.bodies.tail.map(_.centre.x).max shouldBe (30 + 119 * 0.4) +- 1e-9
    layout.freeBodies.size shouldBe 9601
  }
