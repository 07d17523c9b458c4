package sims.dynamics.joints

/** A joint's motor: it drives the joint's coordinate at `speed` (rad/s for a revolute or wheel
  * joint, m/s for a prismatic one) with at most `maxForce` (a torque in N m for the turning
  * joints, a force in N for the sliding one), as an electric motor with a speed controller.
  *
  * @param speed the speed the motor drives towards
  * @param maxForce the largest torque or force it may use, at least 0
  */
final case class JointMotor(speed: Double, maxForce: Double):
  if speed.isNaN || speed.isInfinite then throw IllegalArgumentException(s"speed must be finite, got $speed")
  if !(maxForce >= 0) || maxForce.isInfinite then
    throw IllegalArgumentException(s"maxForce must be finite and at least 0, got $maxForce")

  override def toString: String = s"JointMotor(speed = $speed, maxForce = $maxForce)"
