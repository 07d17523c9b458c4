package sims.scenes

import sims.dynamics.{Body, Capsule, Circle, Edge, HullPolygon, Shape}
import sims.geometry.Vector2D

/** Convex hulls of point sets, capsules and balls dropped into a valley whose outline is a
  * fixed body of edges.
  */
object Shapes extends Scene:
  /** The valley's outline, left to right: one edge between each two neighbours. */
  val Outline: Seq[Vector2D] =
    Seq(Vector2D(-8.5, 6), Vector2D(-6, 2), Vector2D(-2.5, 0), Vector2D(2.5, 0), Vector2D(6, 2), Vector2D(8.5, 6))

  /** Point sets whose hulls are dropped: a rock, a wedge, a kite and a slab (points inside the
    * hulls are dropped by HullPolygon).
    */
  private val PointSets: Seq[Seq[Vector2D]] = Seq(
    Seq(Vector2D(-0.5, -0.3), Vector2D(0.1, -0.45), Vector2D(0.55, 0), Vector2D(0.2, 0.4), Vector2D(-0.4, 0.3),
      Vector2D(0, 0)),
    Seq(Vector2D(-0.6, -0.25), Vector2D(0.6, -0.25), Vector2D(-0.6, 0.35)),
    Seq(Vector2D(0, -0.5), Vector2D(0.35, 0.1), Vector2D(0, 0.4), Vector2D(-0.35, 0.1), Vector2D(0, 0.1)),
    Seq(Vector2D(-0.7, -0.15), Vector2D(0.7, -0.15), Vector2D(0.6, 0.15), Vector2D(-0.6, 0.15)))

  def name: String = "Shapes"
  def description: String = "Convex hulls of point sets, capsules and balls dropped into a valley of edges."
  def view: Region = Region(-9, -1, 9, 9)
  override def region: Region = Region(-8.5, -0.5, 8.5, 10)

  /** The falling shape at index `i`: hulls, capsules and balls in turn. */
  private def shapeFor(i: Int): Shape = i % 3 match
    case 0 => HullPolygon(PointSets(i / 3 % PointSets.length), 1)
    case 1 => Capsule(0.3 + 0.1 * (i % 4), 0.12 + 0.04 * (i % 3), 1)
    case _ => Circle(0.2 + 0.05 * (i % 4), 1)

  def build(): Staged =
    val valley = Body(Outline.sliding(2).map(pair => Edge(pair(0), pair(1))).toSeq*) // fixed: it has edges
    val world = Scene.worldOf(valley)
    for i <- 0 until 18 do
      val shape = shapeFor(i)
      shape.pos = Vector2D(-4 + 1.6 * (i % 6), 2.5 + 1.4 * (i / 6))
      shape.rotation = 0.4 * (i % 5)
      world += shape.asBody
    Staged(world)
