package sims.collision

import sims.dynamics.Shape
import sims.geometry.Vector2D

/** A pair of shapes in contact after a step, as the world's solver saw it: a copy, valid for
  * as long as it is kept (see `World.contacts`).
  *
  * @param shape1 the first shape (the classic step's reference shape)
  * @param shape2 the second shape
  * @param normal unit normal, pointing away from `shape1`
  * @param points the contact points, world coordinates
  * @param separations per point, the distance between the surfaces along the normal: negative
  *   where they overlap; the soft step also keeps points up to its speculative distance apart
  * @param normalImpulses per point, the normal impulse of the last substep (the soft step; the
  *   classic step keeps no impulses and gives 0)
  * @param tangentImpulses per point, the friction impulse of the last substep (0 in the classic step)
  * @param totalNormalImpulses per point, the normal impulse applied over the whole step: every
  *   substep's and restitution's, N s (the soft step; 0 in the classic step). The strength of an
  *   impact, e.g. to play a sound; a speculative point with a positive total has met its shape.
  */
final case class Contact(shape1: Shape, shape2: Shape, normal: Vector2D, points: IndexedSeq[Vector2D],
    separations: IndexedSeq[Double], normalImpulses: IndexedSeq[Double], tangentImpulses: IndexedSeq[Double],
    totalNormalImpulses: IndexedSeq[Double]):

  /** True if the shapes touch or overlap at some point (separation at most 0). */
  def touching: Boolean = separations.exists(_ <= 0)
