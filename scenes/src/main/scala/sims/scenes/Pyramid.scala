package sims.scenes

import sims.geometry.Vector2D

/** A pyramid of boxes, 10 rows: the harder stacking test. */
object Pyramid extends Scene:
  /** Rows of the pyramid (the bottom one has this many boxes). */
  val Rows = 10
  private val Half = 0.25

  def name: String = "Pyramid"
  def description: String = s"A pyramid of ${Rows * (Rows + 1) / 2} boxes."
  def view: Region = Region(-5, -0.5, 5, 6)
  override def region: Region = Region(-5, -0.2, 5, 6)

  def build(): Staged =
    val world = Scene.worldOf(Scene.ground(8))
    for row <- 0 until Rows; i <- 0 until Rows - row do
      val x = (i - (Rows - row - 1) / 2.0) * (2 * Half + 0.02)
      world += Scene.box(Vector2D(x, Half + row * (2 * Half + 0.01)), Half, Half)
    Staged(world)
