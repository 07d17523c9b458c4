package sims.dynamics.joints

/** A joint that acts through forces (a spring, say) rather than by correcting velocities and
  * positions; `applyForce()` runs in phase 2 of every step.
  */
trait ForceJoint:
  /** Applies this joint's forces to its bodies. */
  def applyForce(): Unit
