package sims.solver

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Circle, World}
import sims.geometry.Vector2D

/** Angular momentum under the soft step (issue 25): balls colliding in free space keep it.
  * Before the fix a ball pair's manifold was kept from step to step (contact persistence) with
  * its normal and arms as computed, while the balls rolled past each other: the two impulses
  * of a point then acted at points centimetres apart, a couple.
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
