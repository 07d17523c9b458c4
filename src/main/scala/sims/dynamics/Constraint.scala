package sims.dynamics

/** A condition on the motion of bodies (a joint or a collision), kept by correcting velocities
  * and then positions with impulses (documentation chapter 4).
  */
trait Constraint:
  /** Corrects the bodies' velocities so that the velocity constraint holds; `h` is the time step. */
  def correctVelocity(h: Double): Unit

  /** Corrects the bodies' positions so that the position constraint holds; `h` is the time step. */
  def correctPosition(h: Double): Unit
