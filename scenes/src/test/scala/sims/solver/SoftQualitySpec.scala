package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.dynamics.joints.{DistanceJoint, RevoluteJoint}
import sims.geometry.Vector2D
import sims.prefabs.{Net, Pylon, Ragdoll}
import sims.scenes.{Ballpit, BoxPyramid, SwingingChain}

/** The soft step's quality targets on the bench's scenes or shorter variants that
  * run in seconds; the full-size numbers come from the bench's quality report.
  */
class SoftQualitySpec extends AnyFunSuite with Matchers:

  private def soft(world: World): World =
    world.solver = SoftStep()
    world

  private def free(world: World): IndexedSeq[Body] = world.bodies.filterNot(_.fixed).toIndexedSeq

  test("a pyramid of 10 rows stands after 5 s: mean height >= 98%, top box < 5 cm lower, all at rest") {
    val world = soft(BoxPyramid(10).build().world)
    val boxes = free(world)
    val startMean = boxes.map(_.pos.y).sum / boxes.size
    val startTop = boxes.last.pos.y
    for _ <- 1 to 300 do world.step()
    val mean = boxes.map(_.pos.y).sum / boxes.size
    val fastest = boxes.map(_.linearVelocity.length).max
    info(
      f"mean height ${100 * mean / startMean}%.2f%%, top box ${100 * (startTop - boxes.last.pos.y)}%.2f cm lower, fastest $fastest%.4f m/s")
    mean / startMean should be >= 0.98
    startTop - boxes.last.pos.y should be < 0.05
    fastest should be < 0.1
  }

  test("a pyramid of 30 rows (465 boxes) stands still after 10 s: every box < 6 cm from its start and < 0.05 m/s",
    sims.SlowTest) {
    // Its lower contacts carry up to 30 boxes and are stiffened for it: a stiffness that followed
    // each step's load bounced the whole pyramid (a box 39 cm from its start, 0.33 m/s after 10 s).
    val world = soft(BoxPyramid(30).build().world)
    world.enableSleep = false
    val boxes = free(world)
    val start = boxes.map(_.pos)
    for _ <- 1 to 600 do world.step()
    val drift = boxes.indices.map(i => (boxes(i).pos - start(i)).length).max
    val fastest = boxes.map(_.linearVelocity.length).max
    info(f"largest drift ${100 * drift}%.2f cm, fastest $fastest%.4f m/s")
    drift should be < 0.06
    fastest should be < 0.05
  }

  test("a stack of 12 boxes of 0.5 m, staggered by millimetres, stands 30 s: top < 10 cm sideways, no tilt > 0.05 rad") {
    val world = soft(World())
    val ground = Rectangle(20, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    world += ground.asBody
    ground.body.fixed = true
    val boxes =
      for i <- 0 until 12 yield
        val r = Rectangle(0.25, 0.25, 1)
        r.pos = Vector2D(0.002 * ((i * 7) % 5 - 2), 0.25 + 0.5 * i)
        world += r.asBody
        r.body
    val topX = boxes.last.pos.x
    var sideways = 0.0
    var tilt = 0.0
    for _ <- 1 to 30 * 60 do
      world.step()
      sideways = math.max(sideways, math.abs(boxes.last.pos.x - topX))
      tilt = math.max(tilt, boxes.map(b => math.abs(b.rotation)).max)
    info(f"top box at most ${100 * sideways}%.2f cm sideways, largest tilt $tilt%.4f rad")
    sideways should be < 0.1
    tilt should be <= 0.05
  }

  test("chain-100 over the last second of 10 s: links stretched < 0.5 m together, none > 1 cm") {
    val world = soft(SwingingChain(100).build().world)
    val joints = world.joints.collect { case j: DistanceJoint => j }
    var total = 0.0
    var worst = 0.0
    for step <- 1 to 600 do
      world.step()
      if step > 540 then
        val stretches = joints.map(j => (j.connection2 - j.connection1).length - j.distance)
        total = math.max(total, stretches.sum)
        worst = math.max(worst, stretches.map(math.abs).max)
    info(f"total stretch at most $total%.4f m, largest link ${100 * worst}%.3f cm")
    total should be < 0.5
    worst should be < 0.01
  }

  test("ballpit-500 after 15 s: no ball outside, none more than 2 cm into the floor, all slower than 1 m/s") {
    val pit = Ballpit(500)
    val world = soft(pit.build().world)
    val balls = free(world)
    for _ <- 1 to 900 do world.step()
    val outside = balls.count(b => math.abs(b.pos.x) + Ballpit.Radius > Ballpit.HalfInner + 0.02 || b.pos.y > pit.wallTop)
    val deepest = -balls.map(_.pos.y - Ballpit.Radius).min
    val fastest = balls.map(_.linearVelocity.length).max
    info(f"$outside outside, deepest ${100 * deepest}%.2f cm into the floor, fastest $fastest%.4f m/s")
    outside shouldBe 0
    deepest should be < 0.02
    fastest should be < 1.0
  }

  test("a ball dropped 1 m with pair restitution 1, 0.5, 0: never above the drop; e = 0.5 rebounds to e^2 within 12%") {
    for e <- Seq(1.0, 0.5, 0.0) do
      val world = soft(World())
      val ground = Rectangle(5, 0.5, 1)
      ground.pos = Vector2D(0, -0.5)
      ground.restitution = 1
      world += ground.asBody
      ground.body.fixed = true
      val ball = Circle(0.1, 1)
      ball.restitution = e
      ball.pos = Vector2D(0, 1.1)
      world += ball.asBody
      val apexes = scala.collection.mutable.ArrayBuffer.empty[Double]
      var previous = 0.0
      for _ <- 1 to 600 do
        world.step()
        val vy = ball.body.linearVelocity.y
        if previous > 0 && vy <= 0 then apexes += ball.body.pos.y - 0.1
        previous = vy
      info(s"e = $e: rebounds to ${apexes.take(3).map(a => f"$a%.4f").mkString(", ")} m of a 1 m drop")
      apexes.foreach(_ should be <= 1.0)
      if e == 0.5 then apexes.head shouldBe 0.25 +- 0.25 * 0.12
      if e == 0 then apexes.forall(_ < 0.01) shouldBe true
  }

  test("the prefabs hold under the soft step: a ragdoll dropped stays pinned, a net and a pylon hang and stand") {
    val world = soft(World())
    val ground = Rectangle(20, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    world += ground.asBody
    ground.body.fixed = true
    val ragdoll = Ragdoll(Vector2D(-4, 3))
    ragdoll.addTo(world)
    val net = Net(8, 6, Vector2D(0, 2))
    net.addTo(world)
    net.node(0, 5).fixed = true
    net.node(7, 5).fixed = true
    val pylon = Pylon(Vector2D(5, 0.15), levels = 6)
    pylon.addTo(world)
    var pinError = 0.0
    for _ <- 1 to 300 do
      world.step()
      for case j: RevoluteJoint <- ragdoll.joints do pinError = math.max(pinError, j.separation)
    val netStretch = net.joints.collect { case j: DistanceJoint => (j.connection2 - j.connection1).length / j.distance - 1 }.max
    val pylonTop = pylon.node(6, 0).pos.y
    info(
      f"ragdoll pins open at most ${1000 * pinError}%.2f mm; net links stretched at most ${100 * netStretch}%.2f%%; pylon top at $pylonTop%.3f m")
    pinError should be < 0.01
    netStretch should be < 0.05
    pylonTop should be > 6 * 1.0 - 0.1
    world.bodies.forall(b => b.pos.isFinite) shouldBe true
  }
