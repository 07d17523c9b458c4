package sims.scenes

import sims.geometry.Vector2D

/** Three balls spinning backwards are set down on three lanes; the more friction, the sooner
  * they stop sliding and roll (friction 0.05, 0.2 and 1, the lanes' is 1; a contact uses the
  * product).
  */
object Friction extends Scene:
  /** Friction coefficients of the three balls, bottom lane to top lane. */
  val Coefficients: Seq[Double] = Seq(0.05, 0.2, 1.0)
  private val Spin = -15.0
  private val LaneGap = 2.0

  def name: String = "Friction"
  def description: String = "Three spinning balls with friction 0.05, 0.2 and 1 set down on the ground."
  def view: Region = Region(-2, -1, 18, 6)
  override def region: Region = Region(-1, -0.2, 30, 6)

  def build(): Staged =
    val world = sims.dynamics.World()
    for (mu, lane) <- Coefficients.zipWithIndex do
      val floor = Scene.fixedBox(Vector2D(14, lane * LaneGap - 0.25), 16, 0.25)
      floor.shapes.foreach(_.friction = 1)
      world += floor
      val ball = Scene.ball(Vector2D(0, lane * LaneGap + 0.5), 0.5)
      ball.shapes.foreach(_.friction = mu)
      ball.angularVelocity = Spin
      world += ball
    Staged(world)
