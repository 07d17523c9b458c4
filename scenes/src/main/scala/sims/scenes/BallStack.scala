package sims.scenes

import sims.geometry.Vector2D

/** The original's first scene: 52 balls poured between two walls onto the ground. */
object BallStack extends Scene:
  /** Number of balls. */
  val Balls = 52
  private val Radius = 0.2
  private val PerRow = 6

  def name: String = "BallStack"
  def description: String = s"Ground and two walls, $Balls balls stacked between them."
  def view: Region = Region(-4, -1, 4, 6)
  override def region: Region = Region(-2, -0.5, 2, 8)

  def build(): Staged =
    val world = sims.dynamics.World()
    world += Scene.ground(3)
    world += Scene.fixedBox(Vector2D(-1.75, 2), 0.25, 2)
    world += Scene.fixedBox(Vector2D(1.75, 2), 0.25, 2)
    for i <- 0 until Balls do
      val row = i / PerRow
      // Every other row is shifted by half a ball so the stack settles instead of standing in columns.
      val x = -1.2 + (i % PerRow) * 0.45 + (if row % 2 == 0 then 0 else 0.12)
      world += Scene.ball(Vector2D(x, 0.3 + row * 0.5), Radius)
    Staged(world)
