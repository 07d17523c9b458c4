package sims.collision.narrowphase

import sims.collision.{CapsuleCollision, CircleCollision, Collision, PolyCircleCollision, PolyCollision}
import sims.dynamics.Shape

/** One candidate pair and what the narrowphase keeps to rerun on it cheaply: the resolved
  * methods, one reusable collision object per built-in kind, and the last result with the
  * bodies' placement counts it was computed at (the same inputs give the same result).
  */
private[sims] final class PairSlot:
  /** The pair's first shape. */
  var first: Shape = null
  /** The pair's second shape. */
  var second: Shape = null
  /** The methods for the pair's shape classes (resolved once per step). */
  var methods: Narrowphase.Resolved = null
  /** This slot's reusable collision objects, one per built-in kind (polygon kinds are lent). */
  var circle: CircleCollision = null
  var polyCircle: PolyCircleCollision = null
  var poly: PolyCollision = null
  var capsule: CapsuleCollision = null
  // The last result and the inputs it was computed from.
  var doneFirst: Shape = null
  var doneSecond: Shape = null
  var donePlacements1: Long = -1
  var donePlacements2: Long = -1
  var result: Collision = null

  /** Forgets the last result (its inputs can no longer be trusted). */
  def invalidate(): Unit =
    doneFirst = null
    doneSecond = null
    result = null
