package sims.collision.broadphase

import scala.collection.mutable.ArrayBuffer
import sims.collision.PairBuffer
import sims.dynamics.Shape

/** The first stage of collision detection: from the shapes' bounding boxes, the pairs of shapes
  * that may touch (candidates for the narrowphase), and the shapes near a box (for queries).
  * Everything it reports depends on the shapes' order and bounds only, never on hash codes.
  */
private[sims] trait Broadphase:
  /** Takes the current bounds of `shapes` (world order), each enlarged by `margin` on every
    * side; shapes that are not collidable are left out.
    */
  def update(shapes: Array[Shape], margin: Double): Unit

  /** Adds every candidate pair of the last `update` to `pairs` once (see [[sims.collision.PairFilter]]),
    * the shape that joined the world first being the pair's first shape.
    */
  def findPairs(pairs: PairBuffer): Unit

  /** Adds to `found`, in world order, every shape of the last `update` whose enlarged bounds
    * overlap the box from (minX, minY) to (maxX, maxY).
    */
  def query(minX: Double, minY: Double, maxX: Double, maxY: Double, found: ArrayBuffer[Shape]): Unit
