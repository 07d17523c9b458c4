package sims.collision

import sims.dynamics.Shape
import sims.geometry.Vector2D

/** Two shapes that began to touch in the last step (see [[ContactEvents]]).
  *
  * @param shape1 the shape of the pair that joined the world first
  * @param shape2 the other shape
  * @param normal unit normal of the contact, from `shape1` towards `shape2`
  * @param point where they touch: the middle of the contact's points, world coordinates
  * @param approachSpeed how fast the two shapes' surfaces approached each other along the
  *   normal at the impact, m/s (at least 0): the classic step's relative normal velocity before
  *   it corrected the contact, the soft step's fastest approach during the step
  * @param normalImpulse the impulse the contact applied during the step, summed over its points
  *   and substeps, N s (the soft step; the classic step keeps no impulses and gives 0)
  */
final case class ContactBegin(shape1: Shape, shape2: Shape, normal: Vector2D, point: Vector2D, approachSpeed: Double,
    normalImpulse: Double):
  /** Whether `shape` is one of the pair. */
  def involves(shape: Shape): Boolean = (shape1 eq shape) || (shape2 eq shape)

  /** Whether a shape of `body` is one of the pair. */
  def involves(body: sims.dynamics.Body): Boolean = (shape1.body eq body) || (shape2.body eq body)

  /** The pair's other shape than `shape`; fails unless `shape` is one of the pair. */
  def other(shape: Shape): Shape = ContactEnd.otherOf(shape1, shape2, shape)

/** Two shapes that stopped touching in the last step, or that cannot touch any more (a shape
  * left the world or stopped colliding): the end of the pair's [[ContactBegin]].
  *
  * @param shape1 the shape of the pair that joined the world first
  * @param shape2 the other shape
  */
final case class ContactEnd(shape1: Shape, shape2: Shape):
  /** Whether `shape` is one of the pair. */
  def involves(shape: Shape): Boolean = (shape1 eq shape) || (shape2 eq shape)

  /** Whether a shape of `body` is one of the pair. */
  def involves(body: sims.dynamics.Body): Boolean = (shape1.body eq body) || (shape2.body eq body)

  /** The pair's other shape than `shape`; fails unless `shape` is one of the pair. */
  def other(shape: Shape): Shape = ContactEnd.otherOf(shape1, shape2, shape)

/** The pairs' shared rule. */
object ContactEnd:
  /** `shape`'s partner in the pair (shape1, shape2); fails unless it is one of them. */
  private[collision] def otherOf(shape1: Shape, shape2: Shape, shape: Shape): Shape =
    if shape1 eq shape then shape2
    else if shape2 eq shape then shape1
    else throw IllegalArgumentException(s"shape $shape is not one of the pair ($shape1, $shape2)")

/** The contact events of a world's last step (`World.contactEvents`): the pairs of shapes that
  * began to touch and those that stopped, each in the shapes' world order (by the first shape's
  * join order, then the second's). Every begin is followed by exactly one end, in a later step:
  * when the shapes come more than [[sims.Defaults.ContactHysteresis]] apart, or at the next step
  * after a shape left the world, stopped colliding (`collidable`, its filter bits, a joint's
  * `collideConnected`, becoming a sensor) or the world stopped detecting collisions, whichever
  * solver steps the world and however often it is switched.
  *
  * What touching means (docs/events.md): under the classic step, the detector found a collision
  * with points in the step (when it corrected velocities or after the last position
  * correction); under the soft step, a contact point is at or below zero separation at the end of
  * the step, or it pushed during the step (its speculative points, up to a few centimetres
  * apart, do not count until they push).
  *
  * The collections are the world's own and are refilled by the next step: read them in the
  * post-step hook or after `step()`, and copy what you want to keep. Their objects are made when
  * first read after a step: a world whose events nobody reads makes none.
  */
final class ContactEvents private[sims] (tracker: PairTracker)
    extends TrackedEvents[ContactBegin, ContactEnd](tracker):

  /** The pairs that began to touch in the last step. */
  def begins: collection.IndexedSeq[ContactBegin] = beginsOfLastStep

  /** The pairs that stopped touching in the last step. */
  def ends: collection.IndexedSeq[ContactEnd] = endsOfLastStep

  /** The pairs touching now (begun and not ended), in world order: (shape1, shape2) as in their
    * [[ContactBegin]].
    */
  def touching: IndexedSeq[(Shape, Shape)] = openPairs

  protected def makeBegin(k: Int): ContactBegin =
    ContactBegin(tracker.beginFirstShape(k), tracker.beginSecondShape(k),
      Vector2D(tracker.beginValue(k, PairTracker.NormalX), tracker.beginValue(k, PairTracker.NormalY)),
      Vector2D(tracker.beginValue(k, PairTracker.PointX), tracker.beginValue(k, PairTracker.PointY)),
      tracker.beginValue(k, PairTracker.ApproachSpeed), tracker.beginValue(k, PairTracker.NormalImpulse))

  protected def makeEnd(k: Int): ContactEnd = ContactEnd(tracker.endFirstShape(k), tracker.endSecondShape(k))

  override def toString: String = s"ContactEvents($counts)"
