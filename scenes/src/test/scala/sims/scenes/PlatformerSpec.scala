package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** The Platformer scene does what its description says, under either step. */
class PlatformerSpec extends AnyFunSuite with Matchers:
  import Platformer.*

  for (label, solver) <- Seq[(String, Solver)]("ClassicStep" -> ClassicStep, "SoftStep" -> SoftStep()) do
    test(s"$label: the platforms keep their prescribed paths and the boxes ride on them for 5 s") {
      val world = Platformer.build().world.asInstanceOf[PlatformWorld]
      world.solver = solver
      val h = world.timeStep
      var widest = 0.0
      var lowest = Double.PositiveInfinity
      for step <- 1 to 300 do
        world.step()
        // Each platform's offset from its start: a triangle wave of Speed, turning every Half steps.
        val phase = step % (2 * Half)
        val offset = Speed * h * (if phase <= Half then phase else 2 * Half - phase)
        (world.glider.pos - (GliderStart + Vector2D(offset, 0))).length should be < 1e-9
        (world.lift.pos - (LiftStart + Vector2D(0, offset))).length should be < 1e-9
        world.glider.rotation shouldBe 0.0
        for (box, platform) <- world.boxes.zip(Seq(world.glider, world.glider, world.lift)) do
          widest = math.max(widest, math.abs(box.pos.x - platform.pos.x))
          lowest = math.min(lowest, box.pos.y - platform.pos.y)
      info(f"boxes at most $widest%.3f m from their platform's middle, at least $lowest%.3f m above it")
      widest should be < 0.6 // carried: on its platform, not far from where it stood
      lowest should be > PlatformHalfHeight + BoxHalf - 0.02 // standing on it (never fell off)
    }
