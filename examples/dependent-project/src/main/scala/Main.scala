import sims.dynamics.{Circle, Rectangle, World}
import sims.geometry.Vector2D

/** Drops a ball on the ground with SiMS taken from the local Ivy repository. */
@main def dependentProject(): Unit =
  val world = World()
  val ground = Rectangle(10, 0.5, 1).asBody
  ground.fixed = true
  val ball = Circle(0.2, 1).asBody
  ball.pos = Vector2D(0, 3)
  world += ground
  world += ball
  for _ <- 1 to 120 do world.step()
  println(f"SiMS as a dependency: the ball rests at y = ${ball.pos.y}%.3f m")
