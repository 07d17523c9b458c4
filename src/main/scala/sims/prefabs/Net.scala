package sims.prefabs

import sims.Defaults

import sims.dynamics.{Body, Circle}
import sims.dynamics.joints.{DistanceJoint, Joint}
import sims.geometry.Vector2D

/** A net of `width` x `height` small circular nodes, each linked to its right and upper
  * neighbours by distance joints (as the original's prefab).
  *
  * @param width      nodes per row (at least 1)
  * @param height     rows (at least 1)
  * @param position   centre of the lower-left node, world coordinates
  * @param spacing    distance between neighbouring nodes, m
  * @param nodeRadius radius of each node's circle, m
  * @param density    density of the nodes, kg/m^2
  */
final class Net(val width: Int, val height: Int, val position: Vector2D, val spacing: Double = Defaults.NetSpacing,
    val nodeRadius: Double = Defaults.NetNodeRadius, val density: Double = Defaults.NetDensity) extends Prefab:
  if width < 1 || height < 1 then throw IllegalArgumentException(s"a Net needs at least 1 x 1 nodes, got $width x $height")
  if !(spacing > 2 * nodeRadius) || spacing.isInfinite then
    throw IllegalArgumentException(s"spacing must be finite and above the node diameter ${2 * nodeRadius}, got $spacing")

  /** The nodes, row by row from the bottom, left to right: node (column, row) is at
    * index `row * width + column`.
    */
  val bodies: IndexedSeq[Body] =
    for row <- 0 until height; column <- 0 until width yield
      val circle = Circle(nodeRadius, density)
      circle.pos = position + Vector2D(column * spacing, row * spacing)
      circle.asBody

  /** The node at (`column`, `row`), counted from the lower left. */
  def node(column: Int, row: Int): Body = bodies(row * width + column)

  /** Joints to the right neighbour, then to the upper neighbour, node by node. */
  val joints: IndexedSeq[Joint] =
    def link(a: Body, b: Body) = DistanceJoint(a, a.pos, b, b.pos)
    for
      row <- 0 until height
      column <- 0 until width
      neighbour <- Seq((column + 1, row), (column, row + 1)) if neighbour._1 < width && neighbour._2 < height
    yield link(node(column, row), node(neighbour._1, neighbour._2))
