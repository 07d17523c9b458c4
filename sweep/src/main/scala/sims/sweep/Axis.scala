package sims.sweep

/** One parameter of a grid and the values it takes, in order.
  *
  * @param name the parameter's name: its column in the result table
  * @param values the values, at least one, each finite
  */
final case class Axis(name: String, values: IndexedSeq[Double]):
  Axis.requireName(name)
  require(values.nonEmpty, s"axis '$name' needs at least one value")
  values.foreach(v => require(!v.isNaN && !v.isInfinite, s"axis '$name' has a non-finite value $v"))

  override def toString: String = s"Axis($name: ${values.size} values from ${values.head} to ${values.last})"

/** Axes of evenly spaced values. */
object Axis:
  /** `count` evenly spaced values from `first` to `last` (both included; one value: `first`). */
  def evenly(name: String, first: Double, last: Double, count: Int): Axis =
    require(count >= 1, s"axis '$name' needs a count of at least 1, got $count")
    require(!first.isNaN && !first.isInfinite, s"axis '$name' needs a finite first value, got $first")
    require(!last.isNaN && !last.isInfinite, s"axis '$name' needs a finite last value, got $last")
    // Each value from its index (not by adding a step), so that no rounding accumulates; the
    // last is `last` itself.
    Axis(name,
      IndexedSeq.tabulate(count)(i =>
        if i == 0 then first else if i == count - 1 then last else first + (last - first) * i / (count - 1)))

  /** The values `first`, `first + step`, ... up to `last` (included if it is on a step). */
  def stepped(name: String, first: Double, last: Double, step: Double): Axis =
    require(step > 0 && !step.isInfinite, s"axis '$name' needs a step above 0, got $step")
    require(last >= first, s"axis '$name' needs last ($last) at least first ($first)")
    // 1e-9 of a step: a last value meant to be on a step is kept despite rounding.
    evenly(name, first, first + step * math.floor((last - first) / step + 1e-9), math.floor((last - first) / step + 1e-9).toInt + 1)

  /** Checked by every parameter: a non-empty name that cannot be taken for a column's syntax. */
  private[sweep] def requireName(name: String): Unit =
    require(name.nonEmpty, "a parameter's name must not be empty")
    require(name.forall(c => c.isLetterOrDigit || c == '_'),
      s"a parameter's name has letters, digits and underscores only, got '$name'")
