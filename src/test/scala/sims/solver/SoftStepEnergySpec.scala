package sims.solver

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.SlowTest
import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, Shape, World}
import sims.geometry.Vector2D

/** Energy under the soft step: restitution at most 1 never makes energy, and
  * restitution 1 keeps it. Before the fix a closed box of 100 balls with restitution 1 went
  * from 57 J to 2e9 J in 60 s: restitution bounced each point from the fastest approach seen in
  * the substeps, which warm starting and neighbouring contacts inflate, and one point after the
  * other, so a ball between two others bounced twice.
  */
class SoftStepEnergySpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  import SoftStepEnergySpec.*

  given noShrink[T]: org.scalacheck.Shrink[T] = org.scalacheck.Shrink.shrinkAny

  for (friction, name) <- Seq((0.0, "no friction"), (sims.Defaults.Friction, "the default friction")) do
    test(s"a closed box of 100 balls with restitution 1 and $name never gains kinetic energy over 60 s", SlowTest) {
      val world = ballBox(friction)
      world.solver = SoftStep()
      val (start, highest, _) = energies(world, 3600)
      start shouldBe 57.0 +- 0.1
      highest should be <= 1.01 * start
    }

  // The box loses energy where an impact presses a ball against another body that was not
  // approaching it (a ball struck against a wall): that contact stops the push plastically and
  // does not bounce (only points approaching at the step's start do), up to 1 J at once. Which
  // balls meet so is chaotic: one run's loss says little (the box as built kept 92.6% with the
  // contacts in list order, 89.0% with the halves interleaved; eight runs with the speeds scaled
  // by 0.8 to 1.2 kept 84 to 94%, on average 89.0% and 88.6%).
  test("with restitutionThreshold = 0 the box of balls keeps on average at least 85% of its energy over 60 s", SlowTest) {
    val kept =
      for k <- 0 until 8 yield
        val world = ballBox(0)
        world.bodies.foreach(b => b.linearVelocity = b.linearVelocity * (0.8 + 0.4 * k / 7))
        world.solver = SoftStep(restitutionThreshold = 0)
        val (start, highest, end) = energies(world, 3600)
        highest should be <= 1.01 * start
        end / start
    kept.sum / kept.length should be >= 0.85
  }

  test("a closed box of circles and polygons with restitution at most 1 never gains more than 1% of its kinetic energy") {
    forAll(boxes, minSuccessful(16)) { box =>
      val world = box.build()
      world.solver = SoftStep(restitutionThreshold = box.threshold)
      val kinetic = kineticEnergy(world)
      val start = kinetic + potentialEnergy(world)
      var highest = start
      for _ <- 1 to 300 do
        world.step()
        highest = math.max(highest, kineticEnergy(world) + potentialEnergy(world))
      withClue(s"$box: ")((highest - start) / kinetic should be <= 0.01)
    }
  }

object SoftStepEnergySpec:
  /** The scene: four fixed walls 1 m thick around 10 x 10 m, no gravity, 100 balls of
    * radius 0.2 on a 1 m grid with Gaussian velocities (sd 2 m/s), every shape with restitution 1.
    */
  def ballBox(friction: Double): World =
    val world = World()
    world.gravity = Vector2D.Null
    addWalls(world, 5, 1, friction)
    val random = scala.util.Random(1)
    for i <- 0 until 10; j <- 0 until 10 do
      val ball = Circle(0.2, 1)
      ball.pos = Vector2D(-4.5 + i, -4.5 + j)
      ball.restitution = 1
      ball.friction = friction
      val body = ball.asBody
      body.linearVelocity = Vector2D(2 * random.nextGaussian(), 2 * random.nextGaussian())
      world += body
    world

  /** Fixed walls 1 m thick around the square [-half, half]^2. */
  def addWalls(world: World, half: Double, restitution: Double, friction: Double): Unit =
    for (x, y, hw, hh) <- Seq((-half - 0.5, 0.0, 0.5, half + 1), (half + 0.5, 0.0, 0.5, half + 1),
        (0.0, -half - 0.5, half + 1, 0.5), (0.0, half + 0.5, half + 1, 0.5)) do
      val wall = Rectangle(hw, hh, 1)
      wall.pos = Vector2D(x, y)
      wall.restitution = restitution
      wall.friction = friction
      val body = wall.asBody
      body.fixed = true
      world += body

  /** Steps `world` `steps` times: its kinetic energy at the start, the highest after a step,
    * and at the end.
    */
  def energies(world: World, steps: Int): (Double, Double, Double) =
    val start = kineticEnergy(world)
    var highest = start
    for _ <- 1 to steps do
      world.step()
      highest = math.max(highest, kineticEnergy(world))
    (start, highest, kineticEnergy(world))

  def kineticEnergy(world: World): Double =
    world.bodies.filterNot(_.fixed).map { b =>
      0.5 * b.mass * (b.linearVelocity dot b.linearVelocity) + 0.5 * b.I * b.angularVelocity * b.angularVelocity
    }.sum

  /** -m g . x summed over the free bodies: its fall is the work of gravity. */
  def potentialEnergy(world: World): Double =
    world.bodies.filterNot(_.fixed).map(b => -b.mass * (world.gravity dot b.pos)).sum

  /** One shape of a random box: kind 0 a circle, 1 a rectangle, 2 to 4 a regular polygon. */
  final case class Piece(kind: Int, size: Double, restitution: Double, friction: Double, velocity: Vector2D, spin: Double)

  /** A closed box of side 2 half with pieces on a grid, the walls' restitution and friction. */
  final case class RandomBox(half: Double, pieces: Seq[Piece], wallRestitution: Double, wallFriction: Double,
      gravity: Boolean, threshold: Double):
    def build(): World =
      val world = World()
      if !gravity then world.gravity = Vector2D.Null
      addWalls(world, half, wallRestitution, wallFriction)
      val perRow = math.floor(2 * half).toInt
      for (piece, i) <- pieces.zipWithIndex do
        val shape: Shape = piece.kind match
          case 0 => Circle(piece.size, 1)
          case 1 => Rectangle(piece.size, 0.6 * piece.size, 1)
          case n => RegularPolygon(n + 1, piece.size, 1)
        shape.pos = Vector2D(-half + 0.5 + i % perRow, -half + 0.5 + i / perRow)
        shape.restitution = piece.restitution
        shape.friction = piece.friction
        val body: Body = shape.asBody
        body.linearVelocity = piece.velocity
        body.angularVelocity = piece.spin
        world += body
      world

  private val pieces: Gen[Piece] =
    for
      kind <- Gen.choose(0, 4)
      size <- Gen.choose(0.1, 0.35)
      restitution <- Gen.oneOf(Gen.const(1.0), Gen.choose(0.0, 1.0))
      friction <- Gen.oneOf(Gen.const(0.0), Gen.choose(0.0, 1.0))
      vx <- Gen.choose(-4.0, 4.0)
      vy <- Gen.choose(-4.0, 4.0)
      spin <- Gen.choose(-3.0, 3.0)
    yield Piece(kind, size, restitution, friction, Vector2D(vx, vy), spin)

  val boxes: Gen[RandomBox] =
    for
      half <- Gen.choose(1.5, 3.0)
      count <- Gen.choose(4, (2 * half).toInt * (2 * half).toInt)
      drawn <- Gen.listOfN(count, pieces)
      wallRestitution <- Gen.oneOf(Gen.const(1.0), Gen.choose(0.0, 1.0))
      wallFriction <- Gen.oneOf(Gen.const(0.0), Gen.choose(0.0, 1.0))
      gravity <- Gen.oneOf(true, false)
      threshold <- Gen.oneOf(0.0, sims.Defaults.RestitutionThreshold)
    yield RandomBox(half, drawn, wallRestitution, wallFriction, gravity, threshold)
