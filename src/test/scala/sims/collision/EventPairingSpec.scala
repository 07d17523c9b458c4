package sims.collision

import scala.collection.mutable
import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.Defaults
import sims.collision.manifold.ManifoldFixtures
import sims.dynamics.{Body, Capsule, Circle, Rectangle, RegularPolygon, Shape, World}
import sims.dynamics.joints.{DistanceJoint, Joint}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep}

/** The pairing law of contact and sensor events, over random scenes under random changes
  * between steps (bodies leaving and joining again, shapes switched off, turned into sensors and
  * back, filter bits, joints keeping bodies apart, bodies fixed, bullets, collision detection off,
  * the solver switched): every begin is followed by exactly one end or is still open, the open
  * pairs are the world's touching pairs, and they are exactly the pairs that touch now, by each
  * step's definition (or, for contacts, within the hysteresis of touching).
  */
class EventPairingSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  import EventPairingSpec.*

  test("property: begins and ends pair up, and the open pairs are the pairs that touch, over random scenes") {
    var begins, ends, sensorBegins, sensorEnds, changes, phase4Only = 0
    forAll(Gen.choose(0L, Long.MaxValue), minSuccessful(40)) { seed =>
      val scene = RandomScene(seed)
      val open = mutable.Map.empty[(Shape, Shape), Int]
      val overlapping = mutable.Map.empty[(Shape, Shape), Int]
      for step <- 1 to 150 do
        changes += scene.change()
        scene.detector.touched.clear()
        scene.world.step()
        val world = scene.world
        // Pairing: a begin opens a pair that was not open; an end closes an open one.
        for e <- world.contactEvents.ends do
          withClue(s"step $step, end of a pair never begun: ") { open.remove((e.shape1, e.shape2)) should not be empty }
          ends += 1
        for b <- world.contactEvents.begins do
          withClue(s"step $step, begin of an open pair: ") { open.put((b.shape1, b.shape2), step) shouldBe None }
          b.shape1.worldIndex should be < b.shape2.worldIndex
          begins += 1
        for e <- world.sensorEvents.ends do
          overlapping.remove((e.sensor, e.visitor)) should not be empty
          sensorEnds += 1
        for b <- world.sensorEvents.begins do
          overlapping.put((b.sensor, b.visitor), step) shouldBe None
          sensorBegins += 1
        world.contactEvents.touching.toSet shouldBe open.keySet
        world.sensorEvents.overlaps.toSet shouldBe overlapping.keySet
        // The pairs that touch now, by the step's own definition, are open; the other open
        // pairs may still collide and are within the hysteresis.
        val touched = scene.touchedNow()
        phase4Only += scene.phase4Only()
        withClue(s"step $step (${world.solver}), touching but not open: ") { (touched -- open.keySet) shouldBe empty }
        for (a, b) <- open.keySet.toSet -- touched do
          withClue(s"step $step (${world.solver}), open but neither touching nor near: $a, $b: ") {
            inWorld(world, a) shouldBe true
            inWorld(world, b) shouldBe true
            world.enableCollisionDetection shouldBe true
            PairFilter.accepts(a, b) shouldBe true
            ManifoldFixtures.distance(a, b) should be <= Defaults.ContactHysteresis + 1e-9
          }
        // Sensors: exactly the overlaps brute force finds (ambiguous grazes left out).
        val expected = scene.overlapsNow()
        for (pair, certain) <- expected if certain do
          withClue(s"step $step, overlap not open: $pair: ") { overlapping.contains(pair) shouldBe true }
        for pair <- overlapping.keySet do
          withClue(s"step $step, open overlap not found: $pair: ") { expected.contains(pair) shouldBe true }
    }
    info(s"$begins contact begins, $ends ends; $sensorBegins sensor begins, $sensorEnds ends; $changes changes; " +
      s"$phase4Only classic pairs touching in phase 4 only")
    begins should be > 500
    ends should be > 300
    sensorBegins should be > 50
    sensorEnds should be > 30
  }

object EventPairingSpec:
  /** The detector of the classic step, recording the collisions its phase 4 found. */
  final class RecordingDetector(world: World) extends GridDetector(world):
    val touched = mutable.Set.empty[(Shape, Shape)]
    override def detect(): Unit =
      super.detect()
      for c <- collisions if c.points.nonEmpty do touched += ordered(c.shape1, c.shape2)

  /** The pair in world order. */
  def ordered(a: Shape, b: Shape): (Shape, Shape) = if a.worldIndex < b.worldIndex then (a, b) else (b, a)

  def inWorld(world: World, shape: Shape): Boolean = shape.body.world eq world

  /** A container with a dozen random shapes, some sensors, changed at random between steps. */
  final class RandomScene(seed: Long):
    private val random = java.util.Random(seed)
    val world: World = World(RecordingDetector(_))
    val detector: RecordingDetector = world.detector.asInstanceOf[RecordingDetector]
    private val free = mutable.ArrayBuffer.empty[Body]
    private val removed = mutable.ArrayBuffer.empty[Body]
    private val joints = mutable.ArrayBuffer.empty[Joint]

    for (x, y, hw, hh) <- Seq((0.0, -0.5, 4.0, 0.5), (-4.25, 2.0, 0.25, 2.5), (4.25, 2.0, 0.25, 2.5)) do
      val wall = Rectangle(hw, hh, 1)
      wall.pos = Vector2D(x, y)
      wall.restitution = 1
      wall.asBody.fixed = true
      world += wall.body
    if random.nextBoolean() then world.solver = SoftStep()
    for _ <- 0 until 6 + random.nextInt(9) do
      val shape = randomShape()
      shape.pos = Vector2D(-3.5 + 7 * random.nextDouble(), 0.3 + 3.5 * random.nextDouble())
      shape.rotation = random.nextDouble() * 3
      if random.nextInt(8) == 0 then shape.sensor = true
      shape.restitution = random.nextDouble() // up to 1: bounces that part within a step
      val body = shape.asBody
      body.linearVelocity = Vector2D(random.nextGaussian() * 5, random.nextGaussian() * 5)
      world += body
      free += body
    // A fixed sensor zone in the middle.
    private val zone = Rectangle(1, 0.75, 1)
    zone.pos = Vector2D(0, 1)
    zone.sensor = true
    zone.asBody.fixed = true
    world += zone.body

    private def randomShape(): Shape = random.nextInt(4) match
      case 0 => Circle(0.15 + 0.25 * random.nextDouble(), 1)
      case 1 => Rectangle(0.1 + 0.3 * random.nextDouble(), 0.1 + 0.3 * random.nextDouble(), 1)
      case 2 => RegularPolygon(3 + random.nextInt(4), 0.2 + 0.2 * random.nextDouble(), 1)
      case _ => Capsule(0.1 + 0.3 * random.nextDouble(), 0.1 + 0.1 * random.nextDouble(), 1)

    private def anyFree(): Option[Body] = if free.isEmpty then None else Some(free(random.nextInt(free.size)))

    /** Maybe changes something (about one step in six); 1 if it did. */
    def change(): Int =
      if world.enableCollisionDetection == false then
        world.enableCollisionDetection = true
        return 1
      if random.nextInt(6) != 0 then return 0
      random.nextInt(11) match
        case 0 => anyFree().foreach { b => // leaves, with its joints
            joints.filter(j => (j.node1 eq b) || (j.node2 eq b)).foreach { j => world -= j; joints -= j }
            world -= b; free -= b; removed += b
          }
        case 1 => if removed.nonEmpty then { val b = removed.remove(0); world += b; free += b }
        case 2 => anyFree().foreach(b => b.shapes.head.collidable = !b.shapes.head.collidable)
        case 3 => anyFree().foreach(b => b.shapes.head.sensor = !b.shapes.head.sensor)
        case 4 => anyFree().foreach { b => b.shapes.head.categoryBits = if b.shapes.head.categoryBits == 1 then 2 else 1 }
        case 5 => anyFree().foreach { b => b.shapes.head.maskBits = if b.shapes.head.maskBits == -1 then ~2 else -1 }
        case 6 => world.solver = if world.solver == ClassicStep then SoftStep() else ClassicStep
        case 7 => world.enableCollisionDetection = false
        case 8 => for a <- anyFree(); b <- anyFree() if a ne b do
            val joint = DistanceJoint(a, a.pos, b, b.pos)
            joint.collideConnected = false
            world += joint
            joints += joint
        case 9 => anyFree().foreach(b => b.fixed = !b.fixed)
        case _ => anyFree().foreach(b => b.bullet = !b.bullet)
      1

    /** The pairs touching in the step just taken, by its solver's definition: the classic step's
      * collisions with points in phase 4 or after its last position correction; the soft step's
      * contacts with a point at or below zero separation or that pushed.
      */
    def touchedNow(): Set[(Shape, Shape)] =
      if !world.enableCollisionDetection then Set.empty
      else if world.solver == ClassicStep then
        detector.touched.toSet ++ world.collisions.filter(_.points.nonEmpty).map(c => ordered(c.shape1, c.shape2))
      else
        world.contacts.filter(c => c.separations.exists(_ <= 0) || c.totalNormalImpulses.exists(_ > 0))
          .map(c => ordered(c.shape1, c.shape2)).toSet

    /** Pairs the classic step's phase 4 found that were gone after its position correction. */
    def phase4Only(): Int =
      if world.solver != ClassicStep || !world.enableCollisionDetection then 0
      else (detector.touched.toSet -- world.collisions.filter(_.points.nonEmpty).map(c => ordered(c.shape1, c.shape2))).size

    /** Every (sensor, visitor) pair the sensor may see whose shapes overlap, with whether the
      * overlap is certain (not a graze within 1e-9 m, where the narrowphase's test may differ).
      */
    def overlapsNow(): Map[(Shape, Shape), Boolean] =
      val shapes = world.shapes
      (for s <- shapes if s.sensor; v <- shapes if PairFilter.sensorSees(s, v) yield
        val d = ManifoldFixtures.distance(s, v)
        (s, v) -> (d, grazes(s, v))
      ).collect { case (pair, (d, graze)) if d == 0 || graze => pair -> !graze }.toMap

    /** True if the shapes are within 1e-9 m of touching, from either side. */
    private def grazes(a: Shape, b: Shape): Boolean =
      val separation = ShapeSeparation()
      separation.measure(a, b) && math.abs(separation.distance) <= 1e-9
