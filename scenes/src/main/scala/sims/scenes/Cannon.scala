package sims.scenes

import sims.dynamics.World
import sims.geometry.Vector2D

/** A pyramid of circles and a cannon ball fired into it; the action fires another ball. */
object Cannon extends Scene:
  /** Muzzle position, m. */
  val Muzzle: Vector2D = Vector2D(-9, 1)
  /** Muzzle velocity of a ball, m/s. */
  val MuzzleVelocity: Vector2D = Vector2D(14, 4)
  private val Rows = 8
  private val Radius = 0.25

  def name: String = "Cannon"
  def description: String = "A ball fired into a pyramid of circles (action: fire again)."
  def view: Region = Region(-10, -0.5, 8, 8)
  override def region: Region = Region(-11, -0.2, 30, 10)

  /** Adds a heavy ball at the muzzle moving at the muzzle velocity. */
  def fire(world: World): Unit =
    val ball = Scene.ball(Muzzle, 0.4, density = 8)
    ball.linearVelocity = MuzzleVelocity
    world += ball

  def build(): Staged =
    // A backstop at the far end of the ground: a ball knocked out of the pyramid rolls for
    // long (under the soft step, with little loss, beyond the ground's end within 5 s).
    val world = Scene.worldOf(Scene.ground(21, centreX = 9), Scene.fixedBox(Vector2D(29.5, 1), 0.5, 1))
    for row <- 0 until Rows; i <- 0 until Rows - row do
      val x = 3 + (i - (Rows - row - 1) / 2.0) * 2 * Radius
      // Rows rest in the hollows of the row below: a circle pyramid, not a column stack.
      world += Scene.ball(Vector2D(x, Radius + row * Radius * math.sqrt(3)), Radius)
    fire(world)
    Staged(world, Some(SceneAction("Fire", () => fire(world))))
