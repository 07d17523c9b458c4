package sims.dynamics.joints

/** The range a joint's coordinate may take: an angle in radians for a revolute joint, a
  * translation in metres for a prismatic or wheel joint. The joint pushes back only when its
  * coordinate would leave the range (a one-sided constraint at each end).
  *
  * @param lower the smallest value allowed
  * @param upper the largest value allowed, at least `lower`
  */
final case class JointLimits(lower: Double, upper: Double):
  if lower.isNaN || lower.isInfinite then throw IllegalArgumentException(s"lower must be finite, got $lower")
  if upper.isNaN || upper.isInfinite then throw IllegalArgumentException(s"upper must be finite, got $upper")
  if lower > upper then throw IllegalArgumentException(s"lower must be at most upper, got lower = $lower, upper = $upper")

  override def toString: String = s"JointLimits(lower = $lower, upper = $upper)"
