package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.Defaults
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D
import sims.io.WorldCodec

/** Sleeping under the soft step: islands fall asleep after resting `Defaults.TimeToSleep`, each
  * waking rule wakes them, the switches per body and world, the sleep state in snapshots and
  * save files, and a woken pile moves as one that never slept.
  */
class SoftStepSleepSpec extends AnyFunSuite with Matchers:
  import SoftStepSleepSpec.*

  test("a resting island falls asleep after TimeToSleep, not before, and then keeps its placement to the bit") {
    val (world, ground, boxes) = stackWorld(3)
    var firstAsleep = -1
    var step = 0
    while step < 240 && firstAsleep < 0 do
      world.step()
      step += 1
      if boxes.forall(!_.isAwake) then firstAsleep = step
    firstAsleep should be > 0
    // At least TimeToSleep of resting, after the boxes settled from their start.
    firstAsleep * world.timeStep should be >= Defaults.TimeToSleep
    // The island sleeps as one: all at the same step, one island number.
    boxes.map(_.sleepIsland).distinct should have size 1
    boxes.foreach(_.linearVelocity shouldBe Vector2D(0, 0))
    ground.isAwake shouldBe true
    val placements = boxes.map(b => (b.pos, b.rotation))
    for _ <- 1 to 120 do world.step()
    boxes.map(b => (b.pos, b.rotation)) shouldBe placements
    boxes.forall(!_.isAwake) shouldBe true
    world.awakeBodyCount shouldBe 1
  }

  test("a settled ball pit sleeps whole; its steps asleep keep every contact, its touching pairs and its placements") {
    val world = World()
    world.solver = SoftStep()
    val walls = Seq(box(3, 0.5, Vector2D(0, -0.5)), box(0.5, 2, Vector2D(-2.5, 1.5)), box(0.5, 2, Vector2D(2.5, 1.5)))
    walls.foreach { w => w.fixed = true; world += w }
    val balls =
      for row <- 0 until 10; column <- 0 until 18 yield
        val ball = Circle(0.1, 1).asBody
        ball.pos = Vector2D(-1.8 + 0.21 * column + 0.01 * (row % 2), 0.12 + 0.22 * row)
        ball
    balls.foreach(world += _)
    settle(world, balls)
    val touching = world.contactEvents.touching
    val contacts = world.contacts.map(c => (c.shape1, c.shape2, c.normalImpulses))
    val placements = balls.map(_.pos)
    touching.size should be > balls.size
    for _ <- 1 to 30 do
      world.step()
      world.contactEvents.begins shouldBe empty
      world.contactEvents.ends shouldBe empty
    world.contactEvents.touching shouldBe touching
    world.contacts.map(c => (c.shape1, c.shape2, c.normalImpulses)) shouldBe contacts
    balls.map(_.pos) shouldBe placements
    // Pushing one ball wakes its island, the whole pit, which then settles again.
    balls(5).applyImpulse(Vector2D(0, 0.05))
    balls.forall(_.isAwake) shouldBe true
    settle(world, balls)
  }

  test("islands apart sleep apart: a moving box keeps its own island awake, not the resting one") {
    val (world, _, boxes) = stackWorld(2)
    val slider = box(0.25, 0.25, Vector2D(-4, 0.25))
    world += slider
    for _ <- 1 to 120 do
      slider.linearVelocity = Vector2D(0.5, slider.linearVelocity.y) // the user keeps it going
      world.step()
    boxes.forall(!_.isAwake) shouldBe true
    slider.isAwake shouldBe true
  }

  test("a contact with an awake body wakes the island: a ball dropped on a sleeping stack") {
    val (world, _, boxes) = asleepStack(3)
    val ball = Circle(0.2, 1).asBody
    ball.pos = Vector2D(0, 3)
    world += ball
    var step = 0
    while step < 120 && boxes.forall(!_.isAwake) do
      world.step()
      step += 1
    // The top box wakes the moment the ball reaches it, and with it every box of its island.
    boxes.forall(_.isAwake) shouldBe true
    ball.pos.y should be > 1.5 + 0.2 - 0.1
  }

  test("a kinematic platform set moving under a sleeping box wakes it and carries it") {
    val world = World()
    world.solver = SoftStep()
    val platform = box(2, 0.25, Vector2D(0, -0.25))
    platform.kinematic = true
    world += platform
    val crate = box(0.5, 0.25, Vector2D(0, 0.25))
    world += crate
    settle(world, Seq(crate))
    platform.linearVelocity = Vector2D(1, 0)
    for _ <- 1 to 60 do world.step()
    crate.isAwake shouldBe true
    platform.pos.x shouldBe 1.0 +- 1e-9
    // Carried by friction: it moved with the platform, still on it.
    crate.pos.x should be > 0.9
    crate.pos.y shouldBe 0.25 +- 0.01
  }

  test("a kinematic body moving alone keeps moving while everything else sleeps") {
    val (world, _, boxes) = asleepStack(2)
    val mover = box(0.2, 0.2, Vector2D(5, 3))
    mover.kinematic = true
    mover.linearVelocity = Vector2D(0, 1)
    world += mover
    settle(world, boxes)
    for _ <- 1 to 60 do world.step()
    mover.pos.y should be > 3.9
  }

  test("a ball far from the sleeping stack wakes nothing") {
    val (world, _, boxes) = asleepStack(3)
    val ball = Circle(0.2, 1).asBody
    ball.pos = Vector2D(3, 3)
    world += ball
    for _ <- 1 to 60 do world.step()
    boxes.forall(!_.isAwake) shouldBe true
    ball.isAwake shouldBe true
  }

  test("the user's velocity, force, torque, impulse, position and rotation each wake the island") {
    val changes: Seq[(String, Body => Unit)] = Seq(
      "linearVelocity" -> (_.linearVelocity = Vector2D(0.1, 0)),
      "angularVelocity" -> (_.angularVelocity = 0.1),
      "force" -> (_.force = Vector2D(1, 0)),
      "torque" -> (_.torque = 1),
      "applyForce" -> (_.applyForce(Vector2D(1, 0))),
      "applyImpulse" -> (b => b.applyImpulse(Vector2D(0.1, 0), b.pos)),
      "pos" -> (b => b.pos = b.pos + Vector2D(0.01, 0)),
      "rotation" -> (b => b.rotation = b.rotation + 0.01),
      "isAwake" -> (_.isAwake = true))
    for (name, change) <- changes do
      withClue(name) {
        val (_, _, boxes) = asleepStack(3)
        change(boxes(1))
        boxes.forall(_.isAwake) shouldBe true
      }
  }

  test("a joint's partner waking wakes the body at its other end, and a joint made to a sleeper wakes it") {
    // Two stacks side by side joined by a distance joint: one island. Waking one box wakes all.
    val (world, _, boxes) = stackWorld(2)
    val other = Seq(box(0.5, 0.25, Vector2D(3, 0.25)), box(0.5, 0.25, Vector2D(3, 0.75)))
    other.foreach(world += _)
    world += DistanceJoint(boxes(1), boxes(1).pos, other(1), other(1).pos)
    settle(world, boxes ++ other)
    (boxes ++ other).map(_.sleepIsland).distinct should have size 1
    other(0).linearVelocity = Vector2D(0.2, 0)
    (boxes ++ other).forall(_.isAwake) shouldBe true
    // A sleeper jointed to a moving body wakes at the next step, and its island with it.
    val (world2, _, stack) = asleepStack(2)
    val swinger = box(0.1, 0.1, Vector2D(2, 3))
    world2 += swinger
    world2 += DistanceJoint(stack(1), stack(1).pos, swinger, swinger.pos)
    world2.step()
    stack.forall(_.isAwake) shouldBe true
    // A sleeper put to sleep by the user next to an awake moving body joined by a joint.
    val (world3, _, stack3) = asleepStack(2)
    val partner = box(0.1, 0.1, Vector2D(2, 3))
    world3 += partner
    world3 += DistanceJoint(stack3(1), stack3(1).pos, partner, partner.pos)
    stack3.foreach(_.isAwake = false)
    world3.step()
    stack3.forall(_.isAwake) shouldBe true
  }

  test("removing a body from a sleeping island wakes it: the box on top of a removed one falls") {
    val (world, _, boxes) = asleepStack(3)
    world -= boxes(0)
    boxes(1).isAwake shouldBe true
    boxes(2).isAwake shouldBe true
    val y = boxes(2).pos.y
    for _ <- 1 to 30 do world.step()
    boxes(2).pos.y should be < y - 0.1
  }

  test("a fixed body moved by the user wakes what sleeps on it; one left alone wakes nothing") {
    val (world, ground, boxes) = asleepStack(2)
    for _ <- 1 to 10 do world.step()
    boxes.forall(!_.isAwake) shouldBe true
    ground.pos = ground.pos + Vector2D(0, -0.2)
    world.step()
    boxes.forall(_.isAwake) shouldBe true
    for _ <- 1 to 20 do world.step()
    boxes(0).pos.y should be < 0.25 - 0.05
    // A fixed wall placed into a sleeping box by the user wakes it, and pushes it out.
    val (world2, _, stack) = asleepStack(1)
    val wall = box(0.5, 1, Vector2D(-3, 1))
    wall.fixed = true
    world2 += wall
    world2.step()
    stack.head.isAwake shouldBe false
    wall.pos = Vector2D(-0.95, 1)
    world2.step()
    stack.head.isAwake shouldBe true
    for _ <- 1 to 30 do world2.step()
    stack.head.pos.x should be > 0.04
  }

  test("per body and per world switches: enableSleep off keeps bodies awake and wakes sleepers") {
    val (world, _, boxes) = stackWorld(2)
    boxes(1).enableSleep = false
    for _ <- 1 to 180 do world.step()
    // One body that may not sleep keeps its whole island awake.
    boxes.forall(_.isAwake) shouldBe true
    boxes(1).enableSleep = true
    settle(world, boxes)
    world.enableSleep = false
    boxes.forall(_.isAwake) shouldBe true
    for _ <- 1 to 180 do world.step()
    boxes.forall(_.isAwake) shouldBe true
    // sleepThreshold 0: the body never rests.
    world.enableSleep = true
    boxes.foreach(_.sleepThreshold = 0)
    for _ <- 1 to 180 do world.step()
    boxes.forall(_.isAwake) shouldBe true
  }

  test("the classic step never puts a body to sleep, and switching to it wakes every body") {
    val (world, _, boxes) = asleepStack(2)
    world.solver = ClassicStep
    boxes.forall(_.isAwake) shouldBe true
    for _ <- 1 to 120 do world.step()
    boxes.forall(_.isAwake) shouldBe true
  }

  test("sleepThreshold is checked where it is given") {
    val b = Circle(1, 1).asBody
    for bad <- Seq(-0.1, Double.NaN, Double.PositiveInfinity) do
      val error = intercept[IllegalArgumentException](b.sleepThreshold = bad)
      error.getMessage should include("sleepThreshold")
      error.getMessage should include(bad.toString)
    b.sleepThreshold shouldBe Defaults.SleepThreshold
  }

  test("a fixed body stays awake; a body put to sleep by the user sleeps with velocities 0") {
    val b = Circle(1, 1).asBody
    b.linearVelocity = Vector2D(1, 2)
    b.isAwake = false
    b.isAwake shouldBe false
    b.linearVelocity shouldBe Vector2D(0, 0)
    val fixed = Circle(1, 1).asBody
    fixed.fixed = true
    fixed.isAwake = false
    fixed.isAwake shouldBe true
  }

  test("snapshots keep the sleep state: restored, the run goes on bit for bit, waking included") {
    val (world, _, boxes) = stackWorld(3)
    for _ <- 1 to 20 do world.step()
    val state = world.snapshot()
    def run(): Seq[(Vector2D, Double, Boolean)] =
      for _ <- 1 to 100 do world.step()
      val ball = Circle(0.2, 1).asBody
      ball.pos = Vector2D(0.1, 2.2)
      world += ball
      val seen =
        for _ <- 1 to 60 yield
          world.step()
          boxes.map(b => (b.pos, b.rotation, b.isAwake))
      world -= ball
      seen.flatten
    val first = run()
    first.exists(!_._3) shouldBe true // some boxes slept in the run
    world.restore(state)
    run() shouldBe first
    // A snapshot taken asleep restores asleep.
    settle(world, boxes)
    val asleep = world.snapshot()
    boxes(0).linearVelocity = Vector2D(1, 0)
    world.restore(asleep)
    boxes.forall(!_.isAwake) shouldBe true
  }

  test("save files keep the sleep state and the switches; the loaded world steps as the saved one") {
    val (world, _, boxes) = asleepStack(3)
    boxes(2).sleepThreshold = 0.02
    world.bodies.head.enableSleep = false
    val loaded = WorldCodec.load(WorldCodec.save(world))
    loaded.bodies.map(_.isAwake) shouldBe world.bodies.map(_.isAwake)
    loaded.bodies.map(_.sleepThreshold) shouldBe world.bodies.map(_.sleepThreshold)
    loaded.bodies.map(_.enableSleep) shouldBe world.bodies.map(_.enableSleep)
    loaded.bodies.map(_.sleepIsland) shouldBe world.bodies.map(_.sleepIsland)
    val loadedAgain = WorldCodec.load(WorldCodec.save(world))
    for w <- Seq(world, loadedAgain) do
      val ball = Circle(0.2, 1).asBody
      ball.pos = Vector2D(0.1, 2.5)
      w += ball
      for _ <- 1 to 90 do w.step()
    loadedAgain.bodies.map(b => (b.pos, b.rotation, b.isAwake)) shouldBe world.bodies.map(b => (b.pos, b.rotation, b.isAwake))
    world.enableSleep = false
    WorldCodec.load(WorldCodec.save(world)).enableSleep shouldBe false
  }

  test("a sleeping pile woken by a dropped ball moves as the same pile kept awake, within 1 mm") {
    def pile(sleep: Boolean): (World, Seq[Body]) =
      val world = World()
      world.solver = SoftStep()
      world.enableSleep = sleep
      val ground = box(10, 0.5, Vector2D(0, -0.5))
      ground.fixed = true
      world += ground
      val boxes =
        for
          row <- 0 until 4
          column <- 0 until 4 - row
        yield box(0.25, 0.25, Vector2D(-0.75 + row * 0.25 + column * 0.5, 0.25 + row * 0.5))
      boxes.foreach(world += _)
      for _ <- 1 to 180 do world.step()
      (world, boxes)
    val (asleep, slept) = pile(sleep = true)
    val (awake, kept) = pile(sleep = false)
    slept.forall(!_.isAwake) shouldBe true
    kept.forall(_.isAwake) shouldBe true
    val top = slept.last.pos
    var woke = false
    for w <- Seq(asleep, awake) do
      val ball = Circle(0.3, 2).asBody
      ball.pos = Vector2D(0.1, 3.5)
      w += ball
      for _ <- 1 to 180 do
        w.step()
        if slept.forall(_.isAwake) then woke = true
    // The ball landed on the pile and woke it, and pushed its top box.
    woke shouldBe true
    asleep.bodies.last.pos.y should be < 3.0
    (slept.last.pos - top).length should be > 0.0
    val apart = kept.indices.map(i => (kept(i).pos - slept(i).pos).length).max
    apart should be < 0.001
  }

object SoftStepSleepSpec:
  def box(halfWidth: Double, halfHeight: Double, at: Vector2D): Body =
    val b = Rectangle(halfWidth, halfHeight, 1).asBody
    b.pos = at
    b

  /** A fixed ground and a stack of `n` 1 x 0.5 m boxes on it, under the soft step. */
  def stackWorld(n: Int): (World, Body, Seq[Body]) =
    val world = World()
    world.solver = SoftStep()
    val ground = box(10, 0.5, Vector2D(0, -0.5))
    ground.fixed = true
    world += ground
    val boxes = for i <- 0 until n yield box(0.5, 0.25, Vector2D(0, 0.25 + 0.5 * i))
    boxes.foreach(world += _)
    (world, ground, boxes)

  /** Steps until every body of `bodies` sleeps; fails after 10 s. */
  def settle(world: World, bodies: Seq[Body]): Unit =
    var steps = 0
    while bodies.exists(_.isAwake) do
      if steps > 600 then throw AssertionError(s"not asleep after $steps steps: ${bodies.map(_.linearVelocity)}")
      world.step()
      steps += 1

  /** A stack of `n` boxes asleep. */
  def asleepStack(n: Int): (World, Body, Seq[Body]) =
    val made @ (world, _, boxes) = stackWorld(n)
    settle(world, boxes)
    made
