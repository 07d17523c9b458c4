package sims.solver

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Circle, World}
import sims.geometry.Vector2D

/** Angular momentum under the soft step: balls colliding in free space keep it. A ball pair's
  * manifold kept from step to step (contact persistence) with its normal and arms as computed
  * while the balls rolled past each other made the two impulses of a point act at points
  * centimetres apart, a couple; a normal kept from the start of a step in which two balls
  * glance off each other pushed along a line that missed their centres at impact.
  */
class SoftStepMomentumSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  import SoftStepMomentumSpec.*

  given noShrink[T]: org.scalacheck.Shrink[T] = org.scalacheck.Shrink.shrinkAny

  test("60 balls colliding in free space keep their angular momentum about the origin within 1% over 10 s") {
    val world = cloud(Cloud(60, 0.6, 0.2, 1.0, 0.3, 2))
    val start = angularMomentum(world)
    var drift = 0.0
    for _ <- 1 to 600 do
      world.step()
      drift = math.max(drift, math.abs(angularMomentum(world) - start))
    info(f"L0 $start%.4f, largest drift $drift%.2e (${drift / math.abs(start) * 100}%.2f%%)")
    drift should be <= 0.01 * math.abs(start)
  }

  for offset <- Seq(0.1, 0.2, 0.3); speed <- Seq(2.0, 6.0) do
    test(f"two equal balls glancing off each other ($offset%.1f m off centre, $speed%.0f m/s) leave as real balls do") {
      val world = World()
      world.gravity = Vector2D.Null
      world.solver = SoftStep(restitutionThreshold = 0)
      val Seq(moving, resting) =
        for x <- Seq(0.0, 1.0) yield
          val ball = Circle(0.2, 1)
          ball.pos = Vector2D(x, if x == 0 then 0.0 else offset)
          ball.restitution = 1
          ball.friction = 0
          val body = ball.asBody
          world += body
          body
      moving.linearVelocity = Vector2D(speed, 0)
      for _ <- 1 to 60 do world.step()
      // Elastic, frictionless, equal masses: the resting ball leaves along the line of centres
      // at impact (sin a = offset / 2r) with the moving one's speed along it; the other keeps the rest.
      val sine = offset / 0.4
      val cosine = math.sqrt(1 - sine * sine)
      val expected = Vector2D(speed * cosine * cosine, speed * cosine * sine)
      (resting.linearVelocity - expected).length should be <= 1e-9 * speed
      (moving.linearVelocity - (Vector2D(speed, 0) - expected)).length should be <= 1e-9 * speed
      math.abs(resting.angularVelocity) should be <= 1e-12
    }

  test("random clouds of balls in free space keep angular momentum to 1% of their bodies' moments") {
    var worst = 0.0
    forAll(clouds, minSuccessful(12)) { shape =>
      val world = cloud(shape)
      val start = angularMomentum(world)
      val moments = momentScale(world)
      var drift = 0.0
      for _ <- 1 to 300 do
        world.step()
        drift = math.max(drift, math.abs(angularMomentum(world) - start))
      worst = math.max(worst, drift / moments)
      withClue(s"$shape: drift $drift of moments $moments: ")(drift should be <= 0.01 * moments)
    }
    info(f"largest drift ${worst * 100}%.3f%% of the moments")
  }

object SoftStepMomentumSpec:
  /** `count` balls of `radius` (default materials) on a grid of `spacing`, shifted by a
    * Gaussian of 0.1 m, with Gaussian velocities of sd `speed` plus `inward` times minus the
    * position (so that they meet), drawn from `seed`.
    */
  final case class Cloud(count: Int, spacing: Double, radius: Double, speed: Double, inward: Double, seed: Long)

  def cloud(shape: Cloud): World =
    val world = World()
    world.gravity = Vector2D.Null
    world.solver = SoftStep()
    val random = scala.util.Random(shape.seed)
    val perRow = 10
    for i <- 0 until shape.count do
      val ball = Circle(shape.radius, 1)
      ball.pos = Vector2D(-3 + (i % perRow) * shape.spacing + 0.1 * random.nextGaussian(),
        -1.5 + (i / perRow) * shape.spacing + 0.1 * random.nextGaussian())
      val body = ball.asBody
      body.linearVelocity = Vector2D(shape.speed * random.nextGaussian() - shape.inward * ball.pos.x,
        shape.speed * random.nextGaussian() - shape.inward * ball.pos.y)
      world += body
    world

  val clouds: Gen[Cloud] =
    for
      count <- Gen.choose(10, 40)
      speed <- Gen.choose(0.5, 3.0)
      inward <- Gen.choose(0.0, 1.0)
      seed <- Gen.choose(0L, 1000000L)
    yield Cloud(count, 0.6, 0.2, speed, inward, seed)

  /** Total angular momentum of the free bodies about the origin. */
  def angularMomentum(world: World): Double =
    world.bodies.filterNot(_.fixed).map(b => b.I * b.angularVelocity + b.mass * (b.pos cross b.linearVelocity)).sum

  /** The sum of the free bodies' angular momenta's sizes: a scale that does not cancel. */
  def momentScale(world: World): Double =
    world.bodies.filterNot(_.fixed).map(b => math.abs(b.I * b.angularVelocity) + math.abs(b.mass * (b.pos cross b.linearVelocity))).sum
