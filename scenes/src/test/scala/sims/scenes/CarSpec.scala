package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The Car scene does what its description says (under the soft step, its only one). */
class CarSpec extends AnyFunSuite with Matchers:
  import Car.*

  test("in 5 s the car drives forwards over the hills on its suspension, never flipping nor sinking into the ground") {
    val (staged, car) = stage()
    val world = staged.world
    val start = car.chassis.pos.x
    var steepest = 0.0
    var lowest = Double.PositiveInfinity
    var highest = Double.NegativeInfinity
    var closest = Double.PositiveInfinity
    for _ <- 1 to 300 do
      world.step()
      for b <- world.bodies do
        withClue(s"t = ${world.time}: ")(b.pos.isFinite && !b.rotation.isNaN && !b.angularVelocity.isNaN shouldBe true)
      steepest = math.max(steepest, math.abs(car.chassis.rotation))
      for axle <- car.axles do
        lowest = math.min(lowest, axle.translation)
        highest = math.max(highest, axle.translation)
      for wheel <- Seq(car.rear, car.front) do closest = math.min(closest, wheel.pos.y - height(wheel.pos.x))
    val driven = car.chassis.pos.x - start
    info(f"drove $driven%.2f m; chassis turned at most $steepest%.3f rad; suspension travel $lowest%.3f .. $highest%.3f m; " +
      f"a wheel's centre at least $closest%.3f m above the hills")
    driven should be > 12.0 // 15.4 m measured: past the first two hills
    car.chassis.pos.x should be > HillsStart + HillLength // over the first hill
    steepest should be < 0.6 // the hills' steepest slope is 0.35 rad; upside down would be pi
    lowest should be >= Travel.lower - 0.02 // within the suspension's limits (soft: a little beyond at most)
    highest should be <= Travel.upper + 0.02
    (highest - lowest) should be > 0.03 // the springs worked: 0.105 m measured
    closest should be > 0.5 * WheelRadius // on the ground, never through it
    // The rear wheel is driven: it turns clockwise about as fast as its motor.
    car.rearAxle.angleSpeed should be < 0.5 * Motor.speed
  }

  test("the terrain is one chain of a few dozen segments, walls at both ends") {
    val points = terrainPoints
    (points.size - 1) shouldBe 50 // 48 along the ground, a wall at each end
    points.head.x shouldBe TerrainStart
    points.last.x shouldBe TerrainEnd
    points.map(_.y).max shouldBe (height(TerrainEnd) + WallHeight)
    val ground = points.drop(1).dropRight(1)
    ground.map(_.y).max should be <= HillHeight
    ground.map(_.y).min shouldBe 0.0
  }
