package sims.io

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.GridDetector
import sims.dynamics.{Body, Capsule, Circle, Edge, HullPolygon, Rectangle, RegularPolygon, Shape, World}
import sims.dynamics.joints.{
  DistanceJoint, JointLimits, JointMotor, JointSpring, MotorJoint, MouseJoint, PrismaticJoint, RevoluteJoint, WeldJoint, WheelJoint
}
import sims.geometry.{AABB, Projection, Vector2D}
import sims.robustness.{RandomScenes, StateHash}
import sims.solver.{ClassicStep, SoftStep, Solver}

/** A saved and loaded world steps to the same bits as the original. */
class WorldCodecSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  import RandomScenes.{given, *}

  /** A random scene plus what the fuzz scenes lack: a body of two shapes, a revolute, a prismatic
    * and a mouse joint, transient shapes, changed materials and settings, and a removed body (so
    * the shapes' join orders have a gap).
    */
  private def scene(spec: SceneSpec, solver: Solver): World =
    val world = build(spec, gravity = true, springs = true, solver)
    val bodies = world.bodies.toIndexedSeq
    val left = Rectangle(0.4, 0.1, 2)
    val right = Circle(0.2, 3)
    right.pos = Vector2D(0.5, 0.1)
    right.rotation = 0.3
    val compound = Body(left, right)
    compound.pos = Vector2D(1.5, 12)
    compound.rotation = 0.7
    compound.angularVelocity = 1
    world += compound
    val doomed = Circle(0.3, 1).asBody
    world += doomed
    world -= doomed
    left.transientShapes = Set(bodies(0).shapes.head)
    right.friction = 0.2
    right.restitution = 0.9
    world += RevoluteJoint(compound, bodies(0), compound.pos + Vector2D(0.2, 0))
    world += PrismaticJoint(bodies(1), bodies(1).pos, compound, compound.pos + Vector2D(0.3, 0.1))
    val mouse = MouseJoint(compound, compound.pos, 50)
    mouse.target = compound.pos + Vector2D(1, 1)
    mouse.frequency = 3
    world += mouse
    world.iterations = 7
    world.detector.asInstanceOf[GridDetector].gridSide = 1.5
    world

  private val solvers = Gen.oneOf[Solver](ClassicStep, SoftStep(),
    SoftStep(substeps = 2, contactHertz = 20,
      jointHertz = 40, directJoints = false, contactPersistence = 0))

  test("saved at step k and loaded, a random scene steps to the same bits as the original for 60 more steps") {
    forAll(sceneSpec, solvers, Gen.choose(0, 40), minSuccessful(30)) { (spec, solver, k) =>
      val world = scene(spec, solver)
      for _ <- 1 to k do world.step()
      val loaded = WorldCodec.load(WorldCodec.save(world))
      StateHash(loaded) shouldBe StateHash(world)
      loaded.solver shouldBe world.solver
      for step <- 1 to 60 do
        world.step()
        loaded.step()
        withClue(s"after ${k + step} steps: ")(StateHash(loaded) shouldBe StateHash(world))
    }
  }

  test("the soft step's contact table is saved: a world switched to the classic step and back replays to the same bits") {
    forAll(sceneSpec, minSuccessful(10)) { spec =>
      val world = scene(spec, SoftStep())
      for _ <- 1 to 20 do world.step()
      world.solver = ClassicStep
      val loaded = WorldCodec.load(WorldCodec.save(world))
      for w <- Seq(world, loaded) do w.solver = SoftStep()
      for _ <- 1 to 30 do { world.step(); loaded.step() }
      StateHash(loaded) shouldBe StateHash(world)
    }
  }

  test("the same world gives the same bytes, and a loaded world saves to the bytes it was loaded from") {
    forAll(sceneSpec, solvers, minSuccessful(10)) { (spec, solver) =>
      val world = scene(spec, solver)
      for _ <- 1 to 10 do world.step()
      val bytes = WorldCodec.save(world)
      WorldCodec.save(world) shouldBe bytes
      WorldCodec.save(WorldCodec.load(bytes)) shouldBe bytes
    }
  }

  test("settings, materials, transient shapes and joints come back as they were") {
    val world = scene((List.fill(3)(BodySpec(0, 0.3, 1, 0, 0, 0, 0, 0, 0.5, 0.5, false)), Nil), SoftStep(substeps = 3))
    world.gravity = Vector2D(1, -3)
    world.enablePositionCorrection = false
    world.timeStep = 1.0 / 120
    world.step()
    val loaded = WorldCodec.load(WorldCodec.save(world))
    loaded.gravity shouldBe Vector2D(1, -3)
    loaded.enablePositionCorrection shouldBe false
    loaded.timeStep shouldBe 1.0 / 120
    loaded.iterations shouldBe 7
    loaded.time shouldBe world.time
    loaded.solver shouldBe SoftStep(substeps = 3)
    loaded.detector.asInstanceOf[GridDetector].gridSide shouldBe 1.5
    loaded.shapes.map(_.toString) shouldBe world.shapes.map(_.toString)
    loaded.shapes.map(s => (s.friction, s.restitution, s.collidable, s.transientShapes.size)) shouldBe
      world.shapes.map(s => (s.friction, s.restitution, s.collidable, s.transientShapes.size))
    loaded.joints.map(_.getClass) shouldBe world.joints.map(_.getClass)
    loaded.joints.last.asInstanceOf[MouseJoint].frequency shouldBe 3
  }

  test("a world with a post-step hook is loaded into a new world of the caller's") {
    val world = scene(RandomScenes.sceneSpec.sample.get, ClassicStep)
    var hooked = 0
    val loaded = WorldCodec.load(WorldCodec.save(world), new World { override def postStep(): Unit = hooked += 1 })
    loaded.step()
    hooked shouldBe 1
    val used = World()
    used += Circle(1, 1).asBody
    intercept[IllegalArgumentException](WorldCodec.load(WorldCodec.save(world), used)).getMessage should
      include("loaded into a new world")
  }

  test("a body placed 1e307 m away, where its mass times its position overflows, is saved and loaded") {
    val world = World()
    val far = Circle(1, 100).asBody
    world += far
    far.pos = Vector2D(1e307, -1e307)
    world.step()
    val loaded = WorldCodec.load(WorldCodec.save(world))
    loaded.bodies.head.pos shouldBe far.pos
    world.step()
    loaded.step()
    StateHash(loaded) shouldBe StateHash(world)
  }

  /** A user's shape: the format does not know it. */
  final class Blob extends Shape:
    val density = 1.0
    val volume = 1.0
    val I = 1.0
    def AABB: AABB = new sims.geometry.AABB(pos, pos)
    def project(axis: Vector2D): Projection = Projection(axis, pos dot axis, pos dot axis)
    def contains(point: Vector2D): Boolean = point == pos

  test("a user's shape type cannot be saved: the error names the type") {
    val world = World()
    world += Blob().asBody
    intercept[IllegalArgumentException](WorldCodec.save(world)).getMessage should include("sims.io.WorldCodecSpec$Blob")
  }

  test("bytes that are not a saved world, of another version or cut short are rejected, naming what is wrong") {
    val bytes = WorldCodec.save(scene(RandomScenes.sceneSpec.sample.get, SoftStep()))
    intercept[IllegalArgumentException](WorldCodec.load("hello world".getBytes)).getMessage should include("not a saved SiMS world")
    val later = bytes.clone()
    later(7) = (WorldCodec.FormatVersion + 1).toByte // the version's last byte
    intercept[IllegalArgumentException](WorldCodec.load(later)).getMessage should
      include(s"format version ${WorldCodec.FormatVersion + 1}")
    intercept[IllegalArgumentException](WorldCodec.load(bytes.take(bytes.length - 3))).getMessage should include("cut short")
    intercept[IllegalArgumentException](WorldCodec.load(bytes ++ Array[Byte](0))).getMessage should include("1 bytes after")
  }

  /** Capsules, an edge ground, a hull polygon, filter bits and a joint whose bodies collide. */
  private def shapesScene(solver: Solver): World =
    val world = World()
    world.solver = solver
    world += Body(Edge(Vector2D(-8, 0), Vector2D(8, -0.5)), Edge(Vector2D(8, -0.5), Vector2D(9, 3)))
    val capsule = Capsule(0.6, 0.2, 1)
    capsule.categoryBits = 2
    capsule.maskBits = ~4
    capsule.groupIndex = -3
    val capsuleBody = capsule.asBody
    capsuleBody.pos = Vector2D(0, 1)
    capsuleBody.rotation = 0.4
    world += capsuleBody
    val hull = HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0.1), Vector2D(0.2, 0.9), Vector2D(0.4, 0.3), Vector2D(0.9, 0.8)), 2)
    hull.categoryBits = 4
    val hullBody = hull.asBody
    hullBody.pos = Vector2D(0.3, 2.5)
    world += hullBody
    val hexagon = RegularPolygon(6, 0.3, 1).asBody
    hexagon.pos = Vector2D(-1, 1.5)
    world += hexagon
    val link = DistanceJoint(capsuleBody, capsuleBody.pos, hexagon, hexagon.pos)
    link.collideConnected = false
    world += link
    world

  test("capsules, edges, hull polygons, filter bits and collideConnected are saved and step to the same bits") {
    for solver <- Seq[Solver](ClassicStep, SoftStep()) do
      val world = shapesScene(solver)
      for _ <- 1 to 25 do world.step()
      val loaded = WorldCodec.load(WorldCodec.save(world))
      loaded.shapes.map(_.toString) shouldBe world.shapes.map(_.toString)
      loaded.shapes.map(s => (s.categoryBits, s.maskBits, s.groupIndex)) shouldBe
        world.shapes.map(s => (s.categoryBits, s.maskBits, s.groupIndex))
      loaded.joints.map(_.collideConnected) shouldBe Seq(false)
      loaded.bodies.head.fixed shouldBe true
      for step <- 1 to 60 do
        world.step()
        loaded.step()
        withClue(s"$solver, step $step: ")(StateHash(loaded) shouldBe StateHash(world))
  }

  /** The world saved in format version 1 as `world-format-1.bin` (in the test resources), made
    * by the library as it was before version 2 and stepped 20 times under the soft step.
    */
  private def formatOneWorld(): World =
    val world = World()
    world.solver = SoftStep()
    val ground = Rectangle(10, 0.5, 1).asBody
    ground.fixed = true
    world += ground
    for i <- 0 until 4 do
      val box = Rectangle(0.5, 0.5, 1).asBody
      box.pos = Vector2D(0.1 * i, 1 + 1.01 * i)
      world += box
    val ball = Circle(0.3, 2).asBody
    ball.pos = Vector2D(3, 2)
    world += ball
    val hexagon = RegularPolygon(6, 0.4, 1).asBody
    hexagon.pos = Vector2D(3, 3)
    world += hexagon
    world += RevoluteJoint(ball, hexagon, Vector2D(3, 2.5))
    for _ <- 1 to 20 do world.step()
    world

  test("a world saved in format version 1 loads: its state, every body awake, and it steps on deterministically") {
    val loaded = fixture(1)
    // The format had no sleep state: loaded, every body is awake.
    loaded.bodies.forall(_.isAwake) shouldBe true
    // Its stack of four boxes settles 1.5 mm differently in 20 steps since loaded contacts keep
    // their stiffness (the file is from before that): close within 5 mm.
    closeAndDeterministic(loaded, formatOneWorld(), () => fixture(1), within = 5e-3)
    WorldCodec.save(loaded)(7) shouldBe WorldCodec.FormatVersion
  }

  /** The fixture `world-format-<version>.bin`, loaded. */
  private def fixture(version: Int): World =
    val stream = getClass.getResourceAsStream(s"/sims/io/world-format-$version.bin")
    val bytes = try stream.readAllBytes()
    finally stream.close()
    bytes(7) shouldBe version // the version's last byte: the file is of the old format
    WorldCodec.load(bytes)

  /** A loaded fixture `loaded` against `world`, its scene stepped as many times by today's
    * library: the same bodies in nearly the same places, `within` m and rad (not to the bit: the soft step's
    * restitution and the elementary functions changed since the files were written), and the
    * fixture, loaded twice, steps on to the same bits.
    */
  private def closeAndDeterministic(loaded: World, world: World, again: () => World, within: Double = 1e-3): Unit =
    loaded.bodies.length shouldBe world.bodies.length
    for (a, b) <- loaded.bodies.zip(world.bodies) do
      (a.pos - b.pos).length should be < within
      math.abs(a.rotation - b.rotation) should be < within
    val twin = again()
    for _ <- 1 to 30 do
      loaded.step()
      twin.step()
    StateHash(twin) shouldBe StateHash(loaded)
    WorldCodec.save(twin).sameElements(WorldCodec.save(loaded)) shouldBe true

  test("a world saved in format version 2 loads: its state, no sensors or bullets, and it steps on deterministically") {
    // world-format-2.bin: `shapesScene` under the soft step, stepped 25 times, saved by the
    // library as it was before version 3.
    val loaded = fixture(2)
    val world = shapesScene(SoftStep())
    for _ <- 1 to 25 do world.step()
    loaded.shapes.exists(_.sensor) shouldBe false
    loaded.bodies.exists(_.bullet) shouldBe false
    closeAndDeterministic(loaded, world, () => fixture(2))
  }

  /** The world saved in format version 3 as `world-format-3.bin`: a box and a ball resting on the
    * ground and a pendulum on a revolute joint, under the soft step, stepped 25 times and saved
    * by the library as it was before version 4 (the soft step then used the detector's broadphase
    * settings; its joints carried their impulses themselves).
    */
  private def formatThreeWorld(): World =
    val world = World()
    world.solver = SoftStep()
    val ground = Rectangle(10, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    ground.asBody.fixed = true
    world += ground.body
    val box = Rectangle(0.5, 0.5, 1).asBody
    box.pos = Vector2D(-3, 0.5)
    world += box
    val ball = Circle(0.2, 1).asBody
    ball.pos = Vector2D(2, 0.3)
    world += ball
    val pivot = Rectangle(0.1, 0.1, 1).asBody
    pivot.pos = Vector2D(5, 4)
    pivot.fixed = true
    world += pivot
    val bob = Circle(0.3, 2).asBody
    bob.pos = Vector2D(6, 4)
    world += bob
    world += RevoluteJoint(pivot, bob, Vector2D(5, 4))
    world

  test("a world saved in format version 3 loads: its state, its joint's impulse and contacts, the soft step's settings") {
    def fixture(): World =
      val stream = getClass.getResourceAsStream("/sims/io/world-format-3.bin")
      val bytes = try stream.readAllBytes()
      finally stream.close()
      bytes(7) shouldBe 3
      WorldCodec.load(bytes)
    val loaded = fixture()
    // The state it was saved in: the same scene stepped as many times by today's library comes
    // close, not to the bit (the soft step's restitution and the elementary functions changed
    // since the file was written).
    val world = formatThreeWorld()
    for _ <- 1 to 25 do world.step()
    for (a, b) <- loaded.bodies.zip(world.bodies) do
      (a.pos - b.pos).length should be < 1e-4
      math.abs(a.rotation - b.rotation) should be < 1e-4
    loaded.solver shouldBe SoftStep() // a version-3 world takes the detector's grid settings: the defaults
    val soft = loaded.carriedStates.collectFirst { case s: sims.solver.soft.SoftWorkspace => s }.get
    soft.table.committed.count should be >= 2 // the box's and the ball's contacts with the ground
    soft.joints.impulsesOf(loaded.joints.head).exists(_ != 0) shouldBe true
    // It steps on as any world, to the same bits from the same bytes.
    val again = fixture()
    for _ <- 1 to 30 do
      loaded.step()
      again.step()
    StateHash(again) shouldBe StateHash(loaded)
    WorldCodec.save(again).sameElements(WorldCodec.save(loaded)) shouldBe true
  }

  /** The world saved in format version 4 as `world-format-4.bin`: `formatThreeWorld` and a box on
    * a prismatic joint, under the soft step, stepped 25 times and saved by the library as it was
    * before version 5 (two impulses per revolute or prismatic joint, a contact point's block one
    * double shorter, no kinematic bodies, ids, names or joint limits).
    */
  private def formatFourWorld(): World =
    val world = formatThreeWorld()
    val pivot = world.bodies(3)
    val slider = Rectangle(0.2, 0.2, 1).asBody
    slider.pos = Vector2D(-6, 3)
    world += slider
    world += PrismaticJoint(pivot, Vector2D(5, 4), slider, Vector2D(-6, 3))
    world

  test("a world saved in format version 4 loads: ids in order, no kinematic bodies, names or limits, its joints' impulses kept") {
    val loaded = fixture(4)
    val world = formatFourWorld()
    for _ <- 1 to 25 do world.step()
    loaded.bodies.map(_.id) shouldBe (0 until 6)
    loaded.bodies.exists(b => b.kinematic || b.name.nonEmpty) shouldBe false
    loaded.joints.collect { case r: RevoluteJoint => r.limits } shouldBe Seq(None)
    val soft = loaded.carriedStates.collectFirst { case s: sims.solver.soft.SoftWorkspace => s }.get
    all(loaded.joints.map(j => soft.joints.impulsesOf(j).exists(_ != 0))) shouldBe true
    closeAndDeterministic(loaded, world, () => fixture(4))
  }

  test("kinematic bodies, damping, names, contact-event switches and the new joints are saved and step to the same bits") {
    val world = World()
    world.solver = SoftStep()
    world.enableContactEvents = false
    val ground = Rectangle(10, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    ground.asBody.fixed = true
    world += ground.body
    val platform = Rectangle(1, 0.1).asBody
    platform.pos = Vector2D(0, 2)
    platform.kinematic = true
    platform.linearVelocity = Vector2D(0.5, 0)
    platform.name = Some("platform")
    world += platform
    val box = Rectangle(0.2, 0.2).asBody
    box.pos = Vector2D(0, 2.3)
    box.linearDamping = 0.3
    box.angularDamping = 0.2
    box.gravityScale = 0.8
    box.shapes.head.enableContactEvents = false
    world += box
    val chassis = Rectangle(1, 0.2).asBody
    chassis.pos = Vector2D(4, 1)
    world += chassis
    val wheel = Circle(0.3).asBody
    wheel.pos = Vector2D(4.8, 0.5)
    world += wheel
    val axle = WheelJoint(chassis, wheel, wheel.pos, Vector2D(0, 1))
    axle.motor = Some(JointMotor(-3, 20))
    axle.limits = Some(JointLimits(-0.2, 0.2))
    axle.name = Some("axle")
    world += axle
    val arm = Rectangle(0.5, 0.05).asBody
    arm.pos = Vector2D(-3.5, 3)
    world += arm
    val hinge = RevoluteJoint(ground.body, arm, Vector2D(-4, 3))
    hinge.limits = Some(JointLimits(-0.5, 0.5))
    hinge.spring = Some(JointSpring(2, 0.3))
    hinge.breakForce = 1e6
    world += hinge
    val glued = Circle(0.1).asBody
    glued.pos = Vector2D(-3, 3)
    world += glued
    world += WeldJoint(arm, glued, Vector2D(-3, 3), angularHertz = 3)
    val follower = Circle(0.2).asBody
    follower.pos = Vector2D(-6, 4)
    world += follower
    world += MotorJoint(ground.body, follower, Some(Vector2D(-6, 5)), maxForce = 5)
    val lift = Rectangle(0.2, 0.2).asBody
    lift.pos = Vector2D(6, 3)
    world += lift
    val rail = PrismaticJoint(ground.body, Vector2D(6, 2), lift, Vector2D(6, 3))
    rail.motor = Some(JointMotor(0.3, 50))
    world += rail
    for _ <- 1 to 20 do world.step()
    val loaded = WorldCodec.load(WorldCodec.save(world))
    StateHash(loaded) shouldBe StateHash(world)
    loaded.enableContactEvents shouldBe false
    loaded.bodyNamed("platform").map(_.kinematic) shouldBe Some(true)
    loaded.bodies(2).linearDamping shouldBe 0.3
    loaded.bodies(2).gravityScale shouldBe 0.8
    loaded.bodies(2).shapes.head.enableContactEvents shouldBe false
    loaded.jointNamed("axle").collect { case w: WheelJoint => w.limits } shouldBe Some(Some(JointLimits(-0.2, 0.2)))
    loaded.joints(1).breakForce shouldBe 1e6
    for _ <- 1 to 40 do
      world.step()
      loaded.step()
    StateHash(loaded) shouldBe StateHash(world)
    WorldCodec.save(loaded) shouldBe WorldCodec.save(world)
  }

  test("save is canonical: worlds equal to the bit save to the same bytes, whatever their contact table's past") {
    for seed <- 1L to 8L; solver <- Seq[Solver](ClassicStep, SoftStep()) do
      val spec = RandomScenes.sceneSpec.pureApply(Gen.Parameters.default, org.scalacheck.rng.Seed(seed))
      val world = scene(spec, solver)
      for _ <- 1 to 30 do world.step()
      // The same state reached another way: loaded, its contact table's arrays fresh (the
      // world's own hold what earlier contacts left in the slots a one-point contact leaves free).
      val twin = WorldCodec.load(WorldCodec.save(world))
      for step <- 1 to 30 do
        world.step()
        twin.step()
        withClue(s"scene $seed, $solver, step $step after loading: ") {
          StateHash(twin) shouldBe StateHash(world)
          val (mine, theirs) = (WorldCodec.save(world), WorldCodec.save(twin))
          val firstDifference = mine.indices.find(i => i >= theirs.length || mine(i) != theirs(i))
          firstDifference shouldBe None
          theirs.length shouldBe mine.length
        }
  }

  /** A box resting on the ground, a ball inside a fixed sensor zone, and a bullet on its way to
    * a thin wall: touching pairs, an overlap and a sweep to come.
    */
  private def eventsScene(solver: Solver): World =
    val world = World()
    world.solver = solver
    val ground = Rectangle(10, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    ground.asBody.fixed = true
    world += ground.body
    val box = Rectangle(0.5, 0.5, 1).asBody
    box.pos = Vector2D(-3, 0.5)
    world += box
    val zone = Rectangle(1, 1, 1)
    zone.pos = Vector2D(0, 6)
    zone.sensor = true
    zone.asBody.fixed = true
    world += zone.body
    val ball = Circle(0.2, 1).asBody
    ball.pos = Vector2D(0, 7.1)
    world += ball
    val wall = Rectangle(0.025, 1, 1)
    wall.pos = Vector2D(6, 2)
    wall.asBody.fixed = true
    world += wall.body
    val shot = Circle(0.1, 4).asBody
    shot.pos = Vector2D(2, 2)
    shot.linearVelocity = Vector2D(100, 5)
    shot.bullet = true
    world += shot
    world

  /** The events of a world's last step, by shape index. */
  private def events(world: World): (Seq[(Int, Int)], Seq[(Int, Int)], Seq[(Int, Int)], Seq[(Int, Int)]) =
    val index = world.shapes.zipWithIndex.toMap
    (world.contactEvents.begins.map(b => (index(b.shape1), index(b.shape2))).toSeq,
      world.contactEvents.ends.map(e => (index(e.shape1), index(e.shape2))).toSeq,
      world.sensorEvents.begins.map(b => (index(b.sensor), index(b.visitor))).toSeq,
      world.sensorEvents.ends.map(e => (index(e.sensor), index(e.visitor))).toSeq)

  test("sensors, bullets and the touching and overlapping pairs are saved: a loaded world replays the same events") {
    for solver <- Seq[Solver](ClassicStep, SoftStep()) do
      val world = eventsScene(solver)
      for _ <- 1 to 5 do world.step()
      // The box rests on the ground and the ball is in the zone: open pairs, saved with the world.
      world.contactEvents.touching should not be empty
      world.sensorEvents.overlaps should have size 1
      val loaded = WorldCodec.load(WorldCodec.save(world))
      loaded.shapes.map(_.sensor) shouldBe world.shapes.map(_.sensor)
      loaded.bodies.map(_.bullet) shouldBe world.bodies.map(_.bullet)
      val index = world.shapes.zipWithIndex.toMap
      val loadedIndex = loaded.shapes.zipWithIndex.toMap
      loaded.contactEvents.touching.map((a, b) => (loadedIndex(a), loadedIndex(b))) shouldBe
        world.contactEvents.touching.map((a, b) => (index(a), index(b)))
      loaded.sensorEvents.overlaps.map((a, b) => (loadedIndex(a), loadedIndex(b))) shouldBe
        world.sensorEvents.overlaps.map((a, b) => (index(a), index(b)))
      var sensorEnds = 0
      for step <- 1 to 60 do
        world.step()
        loaded.step()
        withClue(s"$solver, step $step: ") {
          StateHash(loaded) shouldBe StateHash(world)
          events(loaded) shouldBe events(world)
        }
        sensorEnds += world.sensorEvents.ends.length
      // The ball left the zone, and the bullet met the wall (the stage swept it): both replayed.
      sensorEnds shouldBe 1
      loaded.bodies.last.pos.x should be < 6.0
  }
