package sims.collision

import sims.dynamics.Shape

/** Which pairs of shapes may collide at all (SPEC section 4, broadphase): shapes of different
  * bodies, not both fixed, both collidable, neither transient to the other. The broadphase
  * applies it to every pair whose bounds overlap.
  */
private[sims] object PairFilter:
  /** True if `a` and `b` may collide (their bounds are checked by the caller). */
  def accepts(a: Shape, b: Shape): Boolean =
    (a.body ne b.body) && a.collidable && b.collidable &&
      !(a.body.fixed && b.body.fixed) &&
      (a.transientShapes.isEmpty || !a.transientShapes.contains(b)) &&
      (b.transientShapes.isEmpty || !b.transientShapes.contains(a))
