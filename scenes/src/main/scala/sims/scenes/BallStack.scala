package sims.scenes

import sims.dynamics.{Body, World}
import sims.geometry.Vector2D

/** The original's first scene: balls poured between two walls onto the ground, 52 of them in
  * the examples and the bench; the tests pour other numbers with [[withBalls]].
  */
object BallStack extends Scene:
  /** Number of balls of the scene. */
  val Balls = 52
  /** Ball radius, m. */
  val Radius = 0.2
  private val PerRow = 6
  /** The container's inside: the floor's top face and the walls' inner faces, up to their top. */
  val Inside: Region = Region(-1.5, 0, 1.5, 4)

  def name: String = "BallStack"
  def description: String = s"Ground and two walls, $Balls balls stacked between them."
  def view: Region = Region(-4, -1, 4, 6)
  override def region: Region = Region(-2, -0.5, 2, 8)

  def build(): Staged = Staged(withBalls(Balls)._1)

  /** The scene with `count` balls instead of [[Balls]]: its world (the ground and the two walls
    * are its bodies 0 to 2, the balls follow in rows from the floor up) and its balls.
    */
  def withBalls(count: Int): (World, IndexedSeq[Body]) =
    val world = Scene.worldOf(Scene.container(halfWidth = 3, inner = Inside.maxX, height = Inside.maxY)*)
    val balls =
      for i <- 0 until count yield
        val row = i / PerRow
        // Every other row is shifted by half a ball so the stack settles instead of standing in columns.
        val x = -1.2 + (i % PerRow) * 0.45 + (if row % 2 == 0 then 0 else 0.12)
        val ball = Scene.ball(Vector2D(x, 0.3 + row * 0.5), Radius)
        world += ball
        ball
    (world, balls)
