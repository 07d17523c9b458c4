package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.Defaults
import sims.dynamics.{Circle, Rectangle, Shape, World}
import sims.dynamics.joints.RevoluteJoint
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** World.contactEvents under both steps: one begin and no end for a box at rest, a begin and
  * an end per bounce with the impact's strength, ends for every way a pair can stop colliding,
  * the order, failed steps, snapshots and solvers of a user's.
  */
class ContactEventsSpec extends AnyFunSuite with Matchers:
  import ContactEventsSpec.*

  private val solvers: Seq[Solver] = Seq(ClassicStep, SoftStep())

  for solver <- solvers do
    test(s"$solver: a box resting on the ground begins once and never ends over 10 s, touching all along") {
      val (world, ground) = withGround(solver)
      val box = Rectangle(0.25, 0.25, 1)
      box.pos = Vector2D(0, 0.25)
      world += box.asBody
      val log = record(world, 600)
      log.begins.map(b => (b._2, b._3)) shouldBe Seq((ground, box))
      log.begins.head._1 shouldBe 1
      log.ends shouldBe empty
      world.contactEvents.touching shouldBe IndexedSeq((ground, box))
    }

    test(s"$solver: a dropped ball begins at each bounce with the impact's speed and ends as it leaves") {
      val (world, ground) = withGround(solver)
      val ball = Circle(0.2, 1)
      ball.pos = Vector2D(0, 2.2) // 2 m above the ground
      world += ball.asBody
      val log = record(world, 240)
      log.begins.size should be >= 3
      // Every begin but the last (resting) is followed by its end.
      log.ends.size shouldBe log.begins.size - 1
      for ((b, e) <- log.begins.zip(log.ends)) do e._1 should be > b._1
      val first = log.begins.head._4
      first.shape1 shouldBe ground
      first.shape2 shouldBe ball
      first.normal.x shouldBe 0.0 +- 1e-9
      first.normal.y shouldBe 1.0 +- 1e-9
      first.point.x shouldBe 0.0 +- 1e-9
      first.point.y shouldBe 0.0 +- 0.05
      // Falling 2 m: sqrt(2 g h) = 6.26 m/s, plus at most one step of gravity.
      first.approachSpeed shouldBe math.sqrt(2 * 9.81 * 2) +- 0.2
      log.begins.map(_._4.approachSpeed).sliding(2).foreach(pair => pair(1) should be < pair(0))
      solver match
        case _: SoftStep =>
          // The impulse that stops it and throws it back: between m v and m v (1 + e) and a bit.
          val m = ball.mass
          first.normalImpulse should (be > m * first.approachSpeed and be < m * first.approachSpeed * 1.6)
        case _ => first.normalImpulse shouldBe 0.0
    }

    test(s"$solver: a pair ends at the next step when a body leaves, and begins again when it joins again") {
      val (world, ground) = withGround(solver)
      val box = Rectangle(0.25, 0.25, 1)
      box.pos = Vector2D(0, 0.25)
      world += box.asBody
      for _ <- 1 to 30 do world.step()
      world.contactEvents.touching.size shouldBe 1
      world -= box.body
      world.step()
      world.contactEvents.ends shouldBe Seq(ContactEnd(ground, box))
      world.contactEvents.touching shouldBe empty
      world.step()
      world.contactEvents.ends shouldBe empty
      world += box.body
      world.step()
      world.contactEvents.begins.map(b => (b.shape1, b.shape2)) shouldBe Seq((ground, box))
    }

    test(s"$solver: a body that leaves and joins again between two steps ends its pair and begins it anew") {
      val (world, ground) = withGround(solver)
      val box = Rectangle(0.25, 0.25, 1)
      box.pos = Vector2D(0, 0.25)
      world += box.asBody
      for _ <- 1 to 30 do world.step()
      world -= box.body
      world += box.body
      world.step()
      world.contactEvents.ends shouldBe Seq(ContactEnd(ground, box))
      world.contactEvents.begins.map(b => (b.shape1, b.shape2)) shouldBe Seq((ground, box))
    }

    for (change, apply) <- stoppers do
      test(s"$solver: a resting pair ends at the next step when $change") {
        val (world, ground) = withGround(solver)
        val box = Rectangle(0.25, 0.25, 1)
        box.pos = Vector2D(0, 0.25)
        world += box.asBody
        for _ <- 1 to 30 do world.step()
        world.contactEvents.touching shouldBe IndexedSeq((ground, box))
        apply(world, ground, box)
        world.step()
        world.contactEvents.ends shouldBe Seq(ContactEnd(ground, box))
        world.contactEvents.begins shouldBe empty
        world.contactEvents.touching shouldBe empty
      }

    test(s"$solver: a pair lifted less than the hysteresis stays touching; lifted more, it ends") {
      val (world, ground) = withGround(solver)
      world.gravity = Vector2D.Null
      val box = Rectangle(0.25, 0.25, 1)
      box.pos = Vector2D(0, 0.245)
      world += box.asBody
      world.step()
      world.contactEvents.begins.size shouldBe 1
      box.body.pos = Vector2D(0, 0.25 + 0.6 * Defaults.ContactHysteresis)
      box.body.linearVelocity = Vector2D.Null
      for _ <- 1 to 5 do
        world.step()
        world.contactEvents.ends shouldBe empty
      box.body.pos = Vector2D(0, 0.25 + 2 * Defaults.ContactHysteresis)
      world.step()
      world.contactEvents.ends shouldBe Seq(ContactEnd(ground, box))
    }

    test(s"$solver: events come in world order, begins and ends, and the same run gives the same events") {
      def run(): Seq[String] =
        val (world, _) = withGround(solver)
        for i <- 0 until 8 do
          val ball = Circle(0.2, 1)
          ball.pos = Vector2D(1.5 - 0.41 * i, 0.3 + 0.45 * i)
          world += ball.asBody
        val seen = Seq.newBuilder[String]
        for _ <- 1 to 200 do
          world.step()
          val begins = world.contactEvents.begins.map(b => (b.shape1.worldIndex, b.shape2.worldIndex))
          val ends = world.contactEvents.ends.map(e => (e.shape1.worldIndex, e.shape2.worldIndex))
          begins shouldBe begins.sorted
          ends shouldBe ends.sorted
          for (a, b) <- begins ++ ends do a should be < b
          seen += s"${world.time}: begins $begins ends $ends"
        seen.result()
      val first = run()
      first.count(!_.contains("begins ArrayBuffer()")) should be > 3
      run() shouldBe first
    }

    test(s"$solver: a step that fails in its post-step hook leaves the events and the touching pairs as they were") {
      var fail = false
      val world = new World:
        override def postStep(): Unit = if fail then throw IllegalStateException("hook")
      world.solver = solver
      val ground = groundShape()
      world += ground.body
      val ball = Circle(0.2, 1)
      ball.pos = Vector2D(0, 0.45)
      world += ball.asBody
      var step = 0
      while world.contactEvents.begins.isEmpty do { world.step(); step += 1 }
      val begins = world.contactEvents.begins.toList
      val touching = world.contactEvents.touching
      // The ball is lifted off: the next step would end the pair, but it fails.
      ball.body.pos = Vector2D(0, 3)
      fail = true
      intercept[IllegalStateException](world.step())
      world.contactEvents.begins.toList shouldBe begins
      world.contactEvents.touching shouldBe touching
      fail = false
      world.step()
      world.contactEvents.ends shouldBe Seq(ContactEnd(ground, ball))
    }

    test(s"$solver: a snapshot keeps the touching pairs: a restored world replays the same events") {
      val (world, _) = withGround(solver)
      for i <- 0 until 5 do
        val ball = Circle(0.2, 1)
        ball.pos = Vector2D(0.1 * i, 0.5 + 0.6 * i)
        world += ball.asBody
      for _ <- 1 to 40 do world.step()
      val state = world.snapshot()
      val touching = world.contactEvents.touching
      def events(): Seq[(Seq[(Shape, Shape)], Seq[(Shape, Shape)])] =
        for _ <- 1 to 120 yield
          world.step()
          (world.contactEvents.begins.map(b => (b.shape1, b.shape2)).toSeq,
            world.contactEvents.ends.map(e => (e.shape1, e.shape2)).toSeq)
      val first = events()
      first.exists(_._2.nonEmpty) shouldBe true
      world.restore(state)
      world.contactEvents.begins shouldBe empty
      world.contactEvents.touching shouldBe touching
      events() shouldBe first
    }

  for restitution <- Seq(0.0, 0.5) do
    test(s"SoftStep: a speculative contact that never pushes does not begin; landing begins (restitution $restitution)") {
      // The step's last relax pass counts the touching points of the contacts it solves; a
      // bounce has restitution change the impulses after it, and then the contacts are measured
      // again at the step's end: both must leave a hovering pair out and a landed one in.
      val (world, ground) = withGround(SoftStep())
      world.gravity = Vector2D.Null
      world.enableSleep = false // hovering at rest, they would fall asleep before gravity comes on
      ground.restitution = restitution
      val ball = Circle(0.2, 1)
      ball.pos = Vector2D(-1, 0.21) // 1 cm above the ground: a speculative point, one
      val box = Rectangle(0.25, 0.25, 1)
      box.pos = Vector2D(1, 0.26) // and two
      for shape <- Seq(ball, box) do
        shape.restitution = 1.0
        world += shape.asBody
      val hovering = record(world, 60)
      SoftStep().contacts(world).size shouldBe 2
      hovering.begins shouldBe empty
      world.contactEvents.touching shouldBe empty
      world.gravity = Vector2D(0, -9.81)
      val landing = record(world, 60)
      landing.begins.map(b => (b._2, b._3)).head shouldBe ((ground, ball))
      landing.begins.map(b => (b._2, b._3)).toSet shouldBe Set((ground, ball), (ground, box))
    }

  test("switching solvers keeps a resting pair touching: no end, no begin again") {
    val (world, ground) = withGround(ClassicStep)
    val box = Rectangle(0.25, 0.25, 1)
    box.pos = Vector2D(0, 0.25)
    world += box.asBody
    val log = Log()
    for i <- 1 to 600 do
      if i % 50 == 0 then world.solver = if world.solver == ClassicStep then SoftStep() else ClassicStep
      world.step()
      log.add(world, i)
    log.begins.size shouldBe 1
    log.ends shouldBe empty
  }

  test("a solver of a user's: its contacts with a point at or below zero separation begin, the others end") {
    // A solver that moves nothing and shows the contacts the test gives it.
    var shown = IndexedSeq.empty[Contact]
    object Shown extends Solver:
      def step(world: World): Unit = ()
      def contacts(world: World): IndexedSeq[Contact] = shown
    val (world, ground) = withGround(Shown)
    val ball = Circle(0.2, 1)
    ball.pos = Vector2D(0, 3) // far from the ground: no hysteresis keeps the pair
    world += ball.asBody
    def contact(separation: Double) = Contact(ground, ball, Vector2D(0, 1), IndexedSeq(Vector2D(1, 2)),
      IndexedSeq(separation), IndexedSeq(0.5), IndexedSeq(0.0), IndexedSeq(0.75))
    shown = IndexedSeq(contact(0.01))
    world.step()
    world.contactEvents.begins shouldBe empty
    shown = IndexedSeq(contact(-0.001))
    world.step()
    world.contactEvents.begins shouldBe Seq(ContactBegin(ground, ball, Vector2D(0, 1), Vector2D(1, 2), 0, 0.5))
    world.step()
    world.contactEvents.begins shouldBe empty
    world.contactEvents.ends shouldBe empty
    shown = IndexedSeq.empty
    world.step()
    world.contactEvents.ends shouldBe Seq(ContactEnd(ground, ball))
  }

  test("the classic step reports a collision found before the velocity correction though gone after it") {
    // A ball reaching the ground within a step and thrown back by the correction: its
    // collision exists only in phase 4, yet it is a begin (and its end follows).
    val (world, ground) = withGround(ClassicStep)
    val ball = Circle(0.2, 1)
    ball.restitution = 1
    ground.restitution = 1
    ball.pos = Vector2D(0, 0.199)
    world += ball.asBody
    ball.body.linearVelocity = Vector2D(0, -3)
    world.step()
    world.collisions shouldBe empty // none after the position correction: it moved away
    world.contactEvents.begins.map(b => (b.shape1, b.shape2)) shouldBe Seq((ground, ball))
    world.contactEvents.begins.head.approachSpeed shouldBe (3 + 9.81 / 60) +- 1e-9
    world.step()
    world.contactEvents.ends shouldBe Seq(ContactEnd(ground, ball))
  }

object ContactEventsSpec:
  /** Events of a run: (step, shape1, shape2, event). */
  final class Log:
    val begins = collection.mutable.ArrayBuffer.empty[(Int, Shape, Shape, ContactBegin)]
    val ends = collection.mutable.ArrayBuffer.empty[(Int, Shape, Shape)]
    def add(world: World, step: Int): Unit =
      for b <- world.contactEvents.begins do begins += ((step, b.shape1, b.shape2, b))
      for e <- world.contactEvents.ends do ends += ((step, e.shape1, e.shape2))

  /** Steps `world` `steps` times, recording its events. */
  def record(world: World, steps: Int): Log =
    val log = Log()
    for i <- 1 to steps do
      world.step()
      log.add(world, i)
    log

  /** A fixed ground box whose top is at y = 0. */
  def groundShape(): Rectangle =
    val ground = Rectangle(5, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    ground.asBody.fixed = true
    ground

  /** A world stepped by `solver` with a ground, and the ground's shape. */
  def withGround(solver: Solver): (World, Rectangle) =
    val world = World()
    world.solver = solver
    val ground = groundShape()
    world += ground.body
    (world, ground)

  /** The ways a resting pair can stop colliding between two steps. */
  val stoppers: Seq[(String, (World, Shape, Shape) => Unit)] = Seq(
    "its shape stops being collidable" -> ((_, _, box) => box.collidable = false),
    "its category leaves the other's mask" -> ((_, ground, box) => { box.categoryBits = 2; ground.maskBits = ~2 }),
    "the two join the same negative group" -> ((_, ground, box) => { box.groupIndex = -3; ground.groupIndex = -3 }),
    "it becomes a sensor" -> ((_, _, box) => box.sensor = true),
    "a joint keeps the two bodies apart" ->
      ((world, ground, box) => {
        val hinge = RevoluteJoint(ground.body, box.body, box.pos)
        hinge.collideConnected = false
        world += hinge
      }),
    "it becomes transient to the other" -> ((_, ground, box) => box.transientShapes = Set(ground)),
    "collision detection is switched off" -> ((world, _, _) => world.enableCollisionDetection = false),
    "both bodies become fixed" -> ((_, _, box) => box.body.fixed = true))
