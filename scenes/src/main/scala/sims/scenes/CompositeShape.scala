package sims.scenes

import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, Shape}
import sims.geometry.Vector2D

/** Bodies made of several shapes (a dumbbell, an L, a table, a hammer) dropped on the ground:
  * their centres of mass and inertia come from all their shapes.
  */
object CompositeShape extends Scene:
  def name: String = "CompositeShape"
  def description: String = "Bodies made of several shapes falling onto the ground."
  def view: Region = Region(-6, -0.5, 6, 7)
  override def region: Region = Region(-10, -0.2, 10, 8)

  /** A body of the given shapes, each placed at its offset from `at` with its rotation. */
  private def composite(at: Vector2D, parts: (Shape, Vector2D, Double)*): Body =
    for (shape, offset, rotation) <- parts do
      shape.pos = at + offset
      shape.rotation = rotation
    Body(parts.map(_._1)*)

  def build(): Staged =
    val world = Scene.worldOf(Scene.ground(10))
    val dumbbell = composite(Vector2D(-3.5, 2),
      (Circle(0.4, 1), Vector2D(-0.8, 0), 0.0), (Rectangle(0.6, 0.08, 1), Vector2D.Null, 0.0),
      (Circle(0.4, 1), Vector2D(0.8, 0), 0.0))
    dumbbell.rotation = 0.4
    val letterL = composite(Vector2D(-0.5, 3),
      (Rectangle(0.15, 0.8, 1), Vector2D(-0.45, 0.5), 0.0), (Rectangle(0.6, 0.15, 1), Vector2D(0, -0.15), 0.0))
    val table = composite(Vector2D(2.5, 2),
      (Rectangle(1.0, 0.1, 1), Vector2D(0, 0.5), 0.0),
      (Rectangle(0.08, 0.4, 1), Vector2D(-0.85, 0), 0.0), (Rectangle(0.08, 0.4, 1), Vector2D(0.85, 0), 0.0))
    table.rotation = -0.2
    val hammer = composite(Vector2D(0.5, 5.5),
      (Rectangle(0.06, 0.7, 1), Vector2D.Null, 0.0), (RegularPolygon(6, 0.3, 4), Vector2D(0, 0.8), math.Pi / 6))
    hammer.rotation = 1.0
    Seq(dumbbell, letterL, table, hammer).foreach(world += _)
    Staged(world)
