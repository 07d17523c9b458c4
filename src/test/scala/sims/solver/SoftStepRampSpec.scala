package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Rectangle, World}
import sims.geometry.Vector2D

/** Coulomb's friction under the soft step: a box on a fixed ramp with the pair's friction
  * mu = 0.5 (tan of 26.6 degrees) holds on gentler slopes and slides down steeper ones at
  * g (sin a - mu cos a). What the fixes for energy and momentum had to keep.
  */
class SoftStepRampSpec extends AnyFunSuite with Matchers:
  import SoftStepRampSpec.*

  for degrees <- Seq(10.0, 20.0) do
    test(s"a box on a $degrees-degree ramp with mu = 0.5 holds: it moves less than 1 mm in 2 s") {
      val (world, box, down) = ramp(degrees)
      val start = box.pos
      for _ <- 1 to 120 do world.step()
      val moved = (box.pos - start) dot down
      info(f"moved $moved%.2e m")
      math.abs(moved) should be < 1e-3
    }

  test("a box on a 35-degree ramp with mu = 0.5 slides at g (sin a - mu cos a), within 1.3%") {
    val (world, box, down) = ramp(35)
    for _ <- 1 to 120 do world.step()
    val angle = math.toRadians(35)
    val expected = 9.81 * (math.sin(angle) - 0.5 * math.cos(angle))
    val acceleration = (box.linearVelocity dot down) / world.time
    info(f"acceleration $acceleration%.4f m/s^2, expected $expected%.4f (${(acceleration / expected - 1) * 100}%+.2f%%)")
    acceleration shouldBe expected +- 0.013 * expected
  }

object SoftStepRampSpec:
  /** A fixed ramp at `degrees` through the origin and a box of 0.5 m resting on it (pair
    * friction 0.5, no restitution) under the soft step; the box and the downhill direction.
    */
  def ramp(degrees: Double): (World, Body, Vector2D) =
    val world = World()
    world.solver = SoftStep()
    val angle = math.toRadians(degrees)
    val up = Vector2D(-math.sin(angle), math.cos(angle))
    val slab = Rectangle(6, 0.25, 1)
    slab.rotation = angle
    slab.restitution = 0
    slab.friction = math.sqrt(0.5)
    val ground = slab.asBody
    ground.fixed = true
    world += ground
    val square = Rectangle(0.25, 0.25, 1)
    square.pos = up * 0.5
    square.rotation = angle
    square.restitution = 0
    square.friction = math.sqrt(0.5)
    val box = square.asBody
    world += box
    (world, box, Vector2D(-math.cos(angle), -math.sin(angle)))
