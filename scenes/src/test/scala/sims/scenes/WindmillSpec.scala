package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The Windmill scene does what its description says (under the soft step, its only one). */
class WindmillSpec extends AnyFunSuite with Matchers:
  import Windmill.*

  test("the motor brings the rotor to its speed and holds it through the balls' blows; the balls are thrown away") {
    val world = Windmill.build().world.asInstanceOf[WindmillWorld]
    val steps = 900 // 15 s: every ball dropped (the last at 10 s) and come to rest
    var held = 0
    var worst = 0.0
    for step <- 1 to steps do
      world.step()
      val off = math.abs(world.rotor.angularVelocity - Motor.speed)
      if step == 30 then withClue("spun up in half a second: ")(off should be < 1e-3)
      if step > 30 then
        worst = math.max(worst, off)
        if off < 0.01 * math.abs(Motor.speed) then held += 1
    val share = held.toDouble / (steps - 30)
    info(f"within 1%% of the motor's speed in ${100 * share}%.1f%% of the steps after 0.5 s; the hardest blow $worst%.3f rad/s off")
    share should be > 0.9
    worst should be < 0.5 * math.abs(Motor.speed) // no blow stops it
    math.abs(world.rotor.angularVelocity - Motor.speed) should be < 1e-6
    world.axle.angleSpeed shouldBe world.rotor.angularVelocity // the tower stands still
    // Dropped within DropSpread of the hub, the balls end up beyond the blades' reach, most to the
    // right: clockwise, the blades' upper halves move right.
    world.balls.size shouldBe Balls
    (0 until Balls).map(i => math.abs(dropPoint(i).x - Hub.x)).max should be <= DropSpread
    val away = world.balls.count(b => math.abs(b.pos.x - Hub.x) > BladeReach)
    val right = world.balls.count(_.pos.x > Hub.x + BladeReach)
    info(s"$away of $Balls balls beyond the blades' reach, $right of them on the right")
    away should be >= 2 * Balls / 3 // 25 measured
    right should be > away / 2
  }
