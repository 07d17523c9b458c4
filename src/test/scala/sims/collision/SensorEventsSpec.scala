package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, Shape, World}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Sensor shapes under both steps: they never push nor are pushed, yet report the shapes that
  * begin and stop overlapping them, by the rules of the pair filter; and they change nothing for
  * the other pairs.
  */
class SensorEventsSpec extends AnyFunSuite with Matchers:
  import SensorEventsSpec.*

  private val solvers: Seq[Solver] = Seq(ClassicStep, SoftStep())

  for solver <- solvers do
    test(s"$solver: a ball falls through a sensor box exactly as in free fall, and is reported in, then out") {
      def run(withSensor: Boolean): (Seq[(Double, Double, Double)], Seq[String]) =
        val world = World()
        world.solver = solver
        val ball = Circle(0.2, 1)
        ball.pos = Vector2D(0, 4)
        world += ball.asBody
        val zone = fixedBox(0, 1, 1, 0.5)
        zone.sensor = true
        if withSensor then world += zone.body
        val path = Seq.newBuilder[(Double, Double, Double)]
        val events = Seq.newBuilder[String]
        for step <- 1 to 90 do
          world.step()
          path += ((ball.body.pos.x, ball.body.pos.y, ball.body.linearVelocity.y))
          for b <- world.sensorEvents.begins do
            (b.sensor, b.visitor) shouldBe (zone, ball)
            events += s"begin $step"
          for e <- world.sensorEvents.ends do
            (e.sensor, e.visitor) shouldBe (zone, ball)
            events += s"end $step"
          world.contacts shouldBe empty
          if withSensor then
            val inside = ball.body.pos.y - 0.2 <= 1.5 && ball.body.pos.y + 0.2 >= 0.5
            world.sensorEvents.visitors(zone) shouldBe (if inside then Seq(ball) else Nil)
        (path.result(), events.result())
      val (free, none) = run(withSensor = false)
      val (through, events) = run(withSensor = true)
      through shouldBe free // to the bit
      none shouldBe empty
      events.size shouldBe 2
      events.head should startWith("begin")
      events(1) should startWith("end")
    }

    test(s"$solver: a box set on a sensor falls through it; a sensor ball falls through the ground") {
      val world = World()
      world.solver = solver
      world += fixedBox(0, -0.5, 5, 0.5).body
      val pad = fixedBox(2, 0.5, 1, 0.5)
      pad.sensor = true
      world += pad.body
      val box = Rectangle(0.25, 0.25, 1)
      box.pos = Vector2D(2, 1.3)
      world += box.asBody
      val ghost = Circle(0.2, 1)
      ghost.pos = Vector2D(-2, 1)
      ghost.sensor = true
      world += ghost.asBody
      for _ <- 1 to 120 do
        world.step()
        for c <- world.contacts do Seq(c.shape1, c.shape2) should not contain pad
      box.pos.y shouldBe 0.25 +- 0.02 // on the ground, under the pad
      ghost.pos.y should be < -3.0 // fell through the ground: nothing holds a sensor
      world.sensorEvents.overlaps.map(_._2) should not contain ghost
    }

    test(s"$solver: what a sensor sees: other bodies' solid shapes its filters accept; fixed ones unless it is fixed") {
      val world = World()
      world.solver = solver
      world.gravity = Vector2D.Null
      val ground = fixedBox(0, -0.5, 5, 0.5)
      world += ground.body
      val zone = fixedBox(0, 0.5, 3, 1) // fixed, overlapping the fixed ground: not seen
      zone.sensor = true
      world += zone.body
      def ballAt(x: Double): Circle =
        val ball = Circle(0.2, 1)
        ball.pos = Vector2D(x, 0.5)
        world += ball.asBody
        ball
      val plain = ballAt(-2)
      val otherSensor = ballAt(-1.5); otherSensor.sensor = true
      val masked = ballAt(-1); masked.categoryBits = 4; zone.maskBits = ~4
      val grouped = ballAt(-0.5); grouped.groupIndex = -7; zone.groupIndex = -7
      val transient = ballAt(0); transient.transientShapes = Set(zone)
      val off = ballAt(0.5); off.collidable = false
      // A free body with a solid box and a sensor ring around it: the ring sees the ground and
      // the plain ball beside it, never its own box; the zone sees the box and not the ring.
      val solid = Rectangle(0.2, 0.2, 1)
      solid.pos = Vector2D(-2.4, 0.25)
      val ring = Circle(0.5, 1)
      ring.pos = Vector2D(-2.4, 0.25)
      ring.sensor = true
      world += Body(solid, ring)
      world.step()
      world.sensorEvents.overlaps.toSet shouldBe Set((zone, plain), (zone, solid), (ring, ground), (ring, plain))
      world.sensorEvents.begins.map(b => (b.sensor, b.visitor)) shouldBe
        Seq((zone, plain), (zone, solid), (ring, ground), (ring, plain))
    }

    test(s"$solver: an overlap ends at the next step when the visitor leaves, stops colliding or either changes its sensor flag") {
      val changes: Seq[(String, (World, Shape, Shape) => Unit)] = Seq(
        "the visitor's body leaves" -> ((world, _, visitor) => world -= visitor.body),
        "the visitor stops colliding" -> ((_, _, visitor) => visitor.collidable = false),
        "the visitor becomes a sensor" -> ((_, _, visitor) => visitor.sensor = true),
        "the sensor becomes solid" -> ((_, sensor, _) => sensor.sensor = false),
        "the sensor's mask drops the visitor" -> ((_, sensor, _) => sensor.maskBits = 0))
      for (name, change) <- changes do
        withClue(name) {
          val world = World()
          world.solver = solver
          world.gravity = Vector2D.Null
          val zone = fixedBox(0, 0, 2, 2)
          zone.sensor = true
          world += zone.body
          val ball = Circle(0.2, 1)
          world += ball.asBody
          world.step()
          world.sensorEvents.begins.map(_.visitor) shouldBe Seq(ball)
          change(world, zone, ball)
          world.step()
          world.sensorEvents.ends shouldBe Seq(SensorEnd(zone, ball))
          world.sensorEvents.overlaps shouldBe empty
          world.step()
          world.sensorEvents.ends shouldBe empty
        }
    }

    test(s"$solver: sensor bodies added to a scene change no other body's motion, to the bit") {
      def run(withSensors: Boolean): Seq[Vector2D] =
        val world = World()
        world.solver = solver
        world += fixedBox(0, -0.5, 5, 0.5).body
        val balls =
          for i <- 0 until 12 yield
            val ball = Circle(0.2, 1)
            ball.pos = Vector2D(0.13 * (i % 4) - 0.2, 0.3 + 0.42 * i)
            world += ball.asBody
            ball
        if withSensors then
          val zone = fixedBox(0, 1, 5, 1)
          zone.sensor = true
          world += zone.body
          val falling = Circle(0.5, 1)
          falling.pos = Vector2D(0.1, 3)
          falling.sensor = true
          world += falling.asBody
        for _ <- 1 to 240 do world.step()
        if withSensors then world.sensorEvents.overlaps should not be empty
        balls.map(b => b.body.pos) ++ balls.map(b => b.body.linearVelocity)
      run(withSensors = true) shouldBe run(withSensors = false)
    }

  test("sensor events come in world order, sensor first, then visitor") {
    val world = World()
    world.gravity = Vector2D.Null
    val balls =
      for i <- 0 until 4 yield
        val ball = Circle(0.2, 1)
        ball.pos = Vector2D(i * 0.3, 0)
        world += ball.asBody
        ball
    val zones =
      for i <- 0 until 2 yield
        val zone = fixedBox(0.45, 0, 1, 1)
        zone.sensor = true
        world += zone.body
        zone
    world.step()
    world.sensorEvents.begins.map(b => (b.sensor, b.visitor)) shouldBe
      (for z <- zones; b <- balls yield (z, b))
  }

  test("the world counts its sensors as shapes join, leave and change their flag") {
    val world = World()
    val zone = fixedBox(0, 0, 1, 1)
    world += zone.body
    val ball = Circle(0.2, 1)
    world += ball.asBody
    world.gravity = Vector2D.Null
    world.step()
    world.sensorEvents.overlaps shouldBe empty
    zone.sensor = true
    world.step()
    world.sensorEvents.overlaps shouldBe Seq((zone, ball))
    world -= zone.body
    world.step()
    world.sensorEvents.ends shouldBe Seq(SensorEnd(zone, ball))
    world += zone.body
    world.step()
    world.sensorEvents.begins shouldBe Seq(SensorBegin(zone, ball))
  }

object SensorEventsSpec:
  /** A fixed box centred at (x, y) with half extents (hw, hh), as a body's only shape. */
  def fixedBox(x: Double, y: Double, hw: Double, hh: Double): Rectangle =
    val box = Rectangle(hw, hh, 1)
    box.pos = Vector2D(x, y)
    box.asBody.fixed = true
    box
