package sims.scenes

import sims.geometry.Vector2D

/** Ten balls dropped from the same height, restitution 0, 0.1, ..., 0.9 from left to right
  * (the ground's is 1, and a collision uses the product).
  */
object Restitution extends Scene:
  /** Number of balls. */
  val Balls = 10

  def name: String = "Restitution"
  def description: String = s"$Balls balls with restitution 0 to 0.9 bouncing on the ground."
  def view: Region = Region(-6, -0.5, 6, 5)
  override def region: Region = Region(-6, -0.2, 6, 5)

  def build(): Staged =
    val ground = Scene.ground(6)
    ground.shapes.foreach(_.restitution = 1)
    val world = Scene.worldOf(ground)
    for i <- 0 until Balls do
      val ball = Scene.ball(Vector2D(-4.5 + i, 4), 0.3)
      ball.shapes.foreach(_.restitution = i / 10.0)
      world += ball
    Staged(world)
