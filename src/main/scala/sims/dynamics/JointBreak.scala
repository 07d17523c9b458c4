package sims.dynamics

import sims.dynamics.joints.Joint
import sims.geometry.Vector2D

/** A joint that broke in the last step: its reaction exceeded its `breakForce` or `breakTorque`,
  * and the world removed it (`World.jointBreaks`).
  *
  * @param joint the joint, no longer in the world
  * @param force its reaction force on `node2` in the step it broke, N
  * @param torque its reaction torque in that step, N m
  */
final case class JointBreak(joint: Joint, force: Vector2D, torque: Double):
  override def toString: String = s"JointBreak($joint, force = $force, torque = $torque)"
