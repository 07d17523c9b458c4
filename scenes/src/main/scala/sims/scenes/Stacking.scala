package sims.scenes

import sims.geometry.Vector2D

/** Five boxes stacked on the ground: the classic test of resting contact. */
object Stacking extends Scene:
  /** Number of boxes. */
  val Boxes = 5

  def name: String = "Stacking"
  def description: String = s"$Boxes boxes stacked on the ground."
  def view: Region = Region(-3, -0.5, 3, 4)
  override def region: Region = Region(-3, -0.2, 3, 4)

  def build(): Staged =
    val world = Scene.worldOf(Scene.ground(5))
    for i <- 0 until Boxes do
      // A small gap between boxes: they land on each other rather than start interpenetrating.
      world += Scene.box(Vector2D(0.05 * (i % 2), 0.25 + i * 0.52), 0.5, 0.25)
    Staged(world)
