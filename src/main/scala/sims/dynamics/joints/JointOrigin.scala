package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** What a joint was made from: its anchors (world coordinates at creation) and both bodies'
  * placements at that moment. A joint made again from these, with its bodies placed as they
  * were, has the same anchors to the bit (for saving a world, `sims.io.WorldCodec`).
  */
private[sims] final class JointOrigin(node1: Body, val anchor1: Vector2D, node2: Body, val anchor2: Vector2D):
  /** node1's centre and rotation at creation. */
  val x1: Double = node1.x
  val y1: Double = node1.y
  val angle1: Double = node1.angle
  /** node2's centre and rotation at creation. */
  val x2: Double = node2.x
  val y2: Double = node2.y
  val angle2: Double = node2.angle
