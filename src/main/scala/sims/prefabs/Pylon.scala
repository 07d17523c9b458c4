package sims.prefabs

import sims.Defaults

import sims.dynamics.{Body, Circle}
import sims.dynamics.joints.{DistanceJoint, Joint}
import sims.geometry.Vector2D

/** A truss tower: two columns of circular nodes, `levels` + 1 nodes high, braced by distance
  * joints along each column, across each level and along one diagonal of every panel
  * (alternating, so the tower is symmetric), as the original's pylon.
  *
  * @param position   centre of the lower-left node, world coordinates
  * @param levels     panels stacked on each other (at least 1)
  * @param width      distance between the two columns, m
  * @param levelHeight height of one panel, m
  * @param nodeRadius radius of each node's circle, m
  * @param density    density of the nodes, kg/m^2
  */
final class Pylon(val position: Vector2D, val levels: Int = Defaults.PylonLevels, val width: Double = Defaults.PylonWidth,
    val levelHeight: Double = Defaults.PylonLevelHeight, val nodeRadius: Double = Defaults.PylonNodeRadius,
    val density: Double = Defaults.PylonDensity) extends Prefab:
  if levels < 1 then throw IllegalArgumentException(s"a Pylon needs at least 1 level, got $levels")
  if !(width > 2 * nodeRadius) || !(levelHeight > 2 * nodeRadius) || width.isInfinite || levelHeight.isInfinite then
    throw IllegalArgumentException(s"width and levelHeight must be finite and above the node diameter, got $width, $levelHeight")

  /** The nodes level by level from the bottom, left node first: level `k` holds indices
    * `2k` (left) and `2k + 1` (right).
    */
  val bodies: IndexedSeq[Body] =
    for level <- 0 to levels; side <- 0 to 1 yield
      val circle = Circle(nodeRadius, density)
      circle.pos = position + Vector2D(side * width, level * levelHeight)
      circle.asBody

  /** The left (`side` 0) or right (`side` 1) node of `level`. */
  def node(level: Int, side: Int): Body = bodies(2 * level + side)

  /** Per level: the crossbar, then per panel above it the two columns and a diagonal. */
  val joints: IndexedSeq[Joint] =
    def link(a: Body, b: Body): Joint = DistanceJoint(a, a.pos, b, b.pos)
    (0 to levels).flatMap { level =>
      val crossbar = link(node(level, 0), node(level, 1))
      if level == levels then Seq(crossbar)
      else
        val diagonal =
          if level % 2 == 0 then link(node(level, 0), node(level + 1, 1))
          else link(node(level, 1), node(level + 1, 0))
        Seq(crossbar, link(node(level, 0), node(level + 1, 0)), link(node(level, 1), node(level + 1, 1)), diagonal)
    }
