package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.Shape
import sims.solver.{ClassicStep, SoftStep}

/** The Sensors scene under both steps: the zone's count, kept from its events, is the number of
  * balls overlapping it at every step; the highlights follow; the zone never touches a ball.
  */
class SensorsSpec extends AnyFunSuite with Matchers:

  for solver <- Seq(ClassicStep, SoftStep()) do
    test(s"$solver: the zone counts exactly the balls overlapping it, highlights them, and pushes none") {
      val staged = Sensors.build()
      val world = staged.world.asInstanceOf[Sensors.SensorWorld]
      world.solver = solver
      val zone = world.zone
      var most = 0
      for _ <- 1 to 420 do
        world.step()
        // Brute force: the balls whose outline reaches into the zone's box.
        val overlapping = world.shapes.filter { s =>
          !s.body.fixed && {
            val dx = math.max(0.0, math.abs(s.pos.x - Sensors.ZoneCentre.x) - Sensors.ZoneHalfWidth)
            val dy = math.max(0.0, math.abs(s.pos.y - Sensors.ZoneCentre.y) - Sensors.ZoneHalfHeight)
            math.hypot(dx, dy) <= 0.2 - 1e-9
          }
        }.toSet
        world.inside.toSet shouldBe overlapping
        world.sensorEvents.visitors(zone).toSet shouldBe overlapping
        for c <- world.contacts do Seq(c.shape1, c.shape2) should not contain zone
        val overlay = staged.overlay()
        overlay.highlighted shouldBe (overlapping ++ (if overlapping.nonEmpty then Set[Shape](zone) else Set.empty))
        overlay.labels.head._2 shouldBe s"inside: ${overlapping.size}  entered: ${world.entered}"
        most = math.max(most, overlapping.size)
      world.bodies.count(!_.fixed) shouldBe Sensors.Balls
      world.entered should be > most
      most should be > 2
    }
