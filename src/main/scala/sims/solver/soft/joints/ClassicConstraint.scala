package sims.solver.soft.joints

import sims.dynamics.joints.Joint
import sims.solver.soft.SoftContext

/** A joint of a kind the soft step has no constraint of its own for (a user's joint): solved by
  * its classic `correctVelocity` in every solve and relax pass of every substep, on the bodies'
  * current velocities and placements (written into the body objects for it and read back
  * after). `correctPosition` is never called: the substeps move the bodies.
  */
private[sims] final class ClassicConstraint(classic: Joint) extends JointConstraint(classic, 0):
  def prepare(context: SoftContext): Unit = ()

  def warmStart(context: SoftContext): Unit = ()

  def solve(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val i1 = classic.node1.index
    val i2 = classic.node2.index
    if i1 >= 0 then bodies.expose(i1)
    if i2 >= 0 then bodies.expose(i2)
    classic.correctVelocity(context.h)
    if i1 >= 0 then bodies.absorb(i1)
    if i2 >= 0 then bodies.absorb(i2)
