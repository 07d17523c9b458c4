package sims.scenes

import sims.geometry.Vector2D

/** A row of dominoes toppled by a rolling ball. */
object Dominoes extends Scene:
  /** Number of dominoes. */
  val Count = 15

  def name: String = "Dominoes"
  def description: String = s"A row of $Count dominoes toppled by a ball."
  def view: Region = Region(-4, -0.5, 12, 4)
  override def region: Region = Region(-5, -0.2, 16, 4)

  def build(): Staged =
    val world = Scene.worldOf(Scene.ground(10, centreX = 5))
    for i <- 0 until Count do world += Scene.box(Vector2D(i * 0.6, 0.5), 0.06, 0.5)
    val ball = Scene.ball(Vector2D(-3, 0.3), 0.3, density = 2)
    ball.linearVelocity = Vector2D(4, 0)
    world += ball
    Staged(world)
