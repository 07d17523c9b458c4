package sims.sweep

/** One parameter of a random sample, drawn uniformly from `[min, max)`.
  *
  * @param name the parameter's name: its column in the result table
  */
final case class Interval(name: String, min: Double, max: Double):
  Axis.requireName(name)
  require(!min.isNaN && !min.isInfinite, s"interval '$name' needs a finite min, got $min")
  require(!max.isNaN && !max.isInfinite, s"interval '$name' needs a finite max, got $max")
  require(max >= min, s"interval '$name' needs max ($max) at least min ($min)")

  /** The value at `u` in [0, 1) of the way from `min` to `max`. */
  def at(u: Double): Double = min + (max - min) * u

  override def toString: String = s"Interval($name: [$min, $max))"
