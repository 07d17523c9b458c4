package sims.scenes

import sims.dynamics.{Circle, Rectangle, RegularPolygon, Shape}
import sims.geometry.Vector2D

/** A large pile to show speed: circles, boxes, triangles and hexagons poured into a long
  * container.
  */
object Pile extends Scene:
  /** Shapes per row. */
  val Columns = 100
  /** Rows of falling shapes. */
  val Rows = 21
  /** Total number of falling shapes. */
  val Count: Int = Columns * Rows
  private val Spacing = 0.42
  private val HalfWidth = 21.5

  def name: String = "Pile"
  def description: String = s"$Count shapes (circles, boxes, triangles, hexagons) piling up in a container."
  def view: Region = Region(-23, -2, 23, 11)
  override def region: Region = Region(-HalfWidth, -0.1, HalfWidth, 11)

  /** The shape of the pile at index `i`: the kinds alternate so every pair of kinds meets. */
  private def shapeFor(i: Int): Shape = i % 4 match
    case 0 => Circle(0.17, 1)
    case 1 => Rectangle(0.15, 0.15, 1)
    case 2 => RegularPolygon(3, 0.2, 1)
    case _ => RegularPolygon(6, 0.18, 1)

  def build(): Staged =
    // Thick ground and walls: under the weight of the pile the solver lets shapes sink in a
    // little, and a thin wall could be passed through.
    val world = Scene.worldOf(
      Scene.fixedBox(Vector2D(0, -2), HalfWidth + 2, 2),
      Scene.fixedBox(Vector2D(-HalfWidth - 1, 5), 1, 5),
      Scene.fixedBox(Vector2D(HalfWidth + 1, 5), 1, 5))
    val left = -(Columns - 1) * Spacing / 2
    for i <- 0 until Count do
      val row = i / Columns
      val column = i % Columns
      val shape = shapeFor(i + row)
      // A small sideways shift per row keeps the shapes from landing exactly on top of each other.
      shape.pos = Vector2D(left + column * Spacing + 0.1 * (row % 3 - 1), 0.3 + row * Spacing)
      shape.rotation = 0.3 * (i % 5)
      world += shape.asBody
    Staged(world)
