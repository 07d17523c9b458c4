package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Circle, Rectangle, World}
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** Restitution 1 under the soft step: a ball keeps its bounce. */
class RestitutionSpec extends AnyFunSuite with Matchers:
  /** The heights a ball of `radius` dropped `drop` m onto the ground (both restitution 1)
    * reaches after each of its first `bounces` bounces, as fractions of the drop.
    */
  private def rebounds(drop: Double, radius: Double, bounces: Int): Seq[Double] =
    val world = World()
    world.solver = SoftStep()
    val ground = Rectangle(5, 0.5).asBody
    ground.pos = Vector2D(0, -0.5)
    ground.fixed = true
    ground.shapes.head.restitution = 1
    world += ground
    val ball = Circle(radius).asBody
    ball.pos = Vector2D(0, drop + radius)
    ball.shapes.head.restitution = 1
    world += ball
    var apexes = Vector.empty[Double]
    var before = 0.0
    while apexes.length < bounces && world.time < 20 do
      world.step()
      val v = ball.linearVelocity.y
      if before > 0 && v <= 0 then apexes :+= (ball.pos.y - radius) / drop
      before = v
    apexes

  test("restitution 1: a dropped ball rebounds to at least 99% of its drop, and no higher, on each of its first bounces") {
    for (drop, radius) <- Seq((1.0, 0.25), (4.0, 0.5), (0.5, 0.1), (2.0, 0.3)) do
      val heights = rebounds(drop, radius, 3)
      info(s"drop $drop m, ball radius $radius m: " + heights.map(h => f"${100 * h}%.2f%%").mkString(", "))
      withClue(s"drop $drop, radius $radius: $heights") {
        heights should have length 3
        all(heights) should be >= 0.99
        all(heights) should be <= 1.0
      }
  }
