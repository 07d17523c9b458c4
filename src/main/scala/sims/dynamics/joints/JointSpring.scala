package sims.dynamics.joints

/** A joint's spring: it pulls the joint's coordinate back towards its value when the joint was
  * made (the revolute joint's angle 0, the prismatic joint's `initialTranslation`, the wheel
  * joint's translation 0) like a damped spring
  * of natural frequency `hertz` and damping ratio `dampingRatio`, whatever the bodies' masses.
  *
  * @param hertz the spring's natural frequency, Hz, positive
  * @param dampingRatio 0 for no damping, 1 for critical damping; at least 0
  */
final case class JointSpring(hertz: Double, dampingRatio: Double = 0.7):
  if !(hertz > 0) || hertz.isInfinite then throw IllegalArgumentException(s"hertz must be positive and finite, got $hertz")
  if !(dampingRatio >= 0) || dampingRatio.isInfinite then
    throw IllegalArgumentException(s"dampingRatio must be finite and at least 0, got $dampingRatio")

  override def toString: String = s"JointSpring(hertz = $hertz, dampingRatio = $dampingRatio)"
