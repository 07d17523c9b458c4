package sims.collision.broadphase

import scala.collection.mutable.ArrayBuffer
import sims.collision.PairBuffer
import sims.dynamics.Shape

/** The first stage of collision detection: from the shapes' bounding boxes, the pairs of shapes
  * that may touch (candidates for the narrowphase), and the shapes near a box (for queries).
  * Everything it reports depends on the shapes' order and bounds only, never on hash codes.
  */
private[sims] trait Broadphase:
  /** Takes the current bounds of the collidable `shapes` (world order), each enlarged by
    * `margin` on every side; shapes that are not collidable and sensors are left out.
    */
  def update(shapes: Array[Shape], margin: Double): Unit

  /** `update`, each shape's bounds also enlarged by how far its body can move in `sweep`
    * seconds at its current speed; with `everyShape`, shapes that are not collidable and sensors
    * are taken too (for queries).
    */
  def update(shapes: Array[Shape], margin: Double, sweep: Double, everyShape: Boolean): Unit

  /** Makes `pairs` every candidate pair of the last `update`, each once (see [[sims.collision.PairFilter]],
    * applied to the shapes' filters and bodies as they were at that `update`), the shape that
    * joined the world first being the pair's first shape.
    */
  def findPairs(pairs: PairBuffer): Unit

  /** Adds to `found`, in world order, every shape of the last `update` whose enlarged bounds
    * overlap the box from (minX, minY) to (maxX, maxY).
    */
  def query(minX: Double, minY: Double, maxX: Double, maxY: Double, found: ArrayBuffer[Shape]): Unit

  /** Offers `visitor` every shape of the last `update` whose enlarged bounds the segment from
    * (fromX, fromY) to (toX, toY) crosses, each once, nearer ones first as far as the grid's
    * cells tell, until no shape can be crossed before the fraction of the segment that the
    * visitor returned last (see [[Broadphase.RayVisitor]]).
    */
  def rayCast(fromX: Double, fromY: Double, toX: Double, toY: Double, visitor: Broadphase.RayVisitor): Unit

/** Types of the broadphase's queries. */
private[sims] object Broadphase:
  /** Receives the shapes along a ray: `visit` is called with a shape and the fraction of the ray
    * beyond which nothing is wanted any more (1 at first), and returns the new such fraction
    * (the fraction of a hit, to find the nearest; the same one, to find all).
    */
  abstract class RayVisitor:
    /** Looks at `shape`, whose bounds the ray crosses before `limit`; returns the new limit. */
    def visit(shape: Shape, limit: Double): Double
