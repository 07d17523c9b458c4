package sims.examples.scenes

import sims.dynamics.{Circle, Rectangle, RegularPolygon, Shape}
import sims.geometry.Vector2D

/** A large pile to show speed: circles, boxes, triangles and hexagons poured into a long
  * container. Also the scene the benchmarks reuse.
  */
object Pile extends Scene:
  /** Shapes per row. */
  val Columns = 60
  /** Rows of falling shapes. */
  val Rows = 35
  /** Total number of falling shapes. */
  val Count: Int = Columns * Rows
  private val Spacing = 0.6
  private val HalfWidth = 19.0

  def name: String = "Pile"
  def description: String = s"$Count shapes (circles, boxes, triangles, hexagons) piling up in a container."
  def view: Region = Region(-21, -1, 21, 23)
  override def region: Region = Region(-HalfWidth, -0.2, HalfWidth, 24)

  /** The shape of the pile at index `i`: the kinds alternate so every pair of kinds meets. */
  private def shapeFor(i: Int): Shape = i % 4 match
    case 0 => Circle(0.25, 1)
    case 1 => Rectangle(0.22, 0.22, 1)
    case 2 => RegularPolygon(3, 0.28, 1)
    case _ => RegularPolygon(6, 0.26, 1)

  def build(): Staged =
    val world = Scene.worldOf(
      Scene.ground(HalfWidth + 1),
      Scene.fixedBox(Vector2D(-HalfWidth - 0.5, 8), 0.5, 8),
      Scene.fixedBox(Vector2D(HalfWidth + 0.5, 8), 0.5, 8))
    val left = -(Columns - 1) * Spacing / 2
    for i <- 0 until Count do
      val row = i / Columns
      val column = i % Columns
      val shape = shapeFor(i + row)
      // A small sideways shift per row keeps the shapes from landing exactly on top of each other.
      shape.pos = Vector2D(left + column * Spacing + 0.15 * (row % 3 - 1), 0.4 + row * Spacing)
      shape.rotation = 0.3 * (i % 5)
      world += shape.asBody
    Staged(world)
