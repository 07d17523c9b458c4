package sims.sweep

/** One run of a sweep: its index, its seed and its parameters' values.
  *
  * @param index the run's place in the sweep, from 0
  * @param seed derived from the sweep's seed and the index alone: a scene that needs random
  *   numbers draws them from it (with [[Seeds.uniform]]), so that any back end gives the same
  * @param names the parameters' names, in the table's order
  * @param values each parameter's value, in the order of `names`
  */
final case class Row(index: Int, seed: Long, names: IndexedSeq[String], values: IndexedSeq[Double]):
  require(names.size == values.size, s"a row needs one value per name, got ${names.size} names and ${values.size} values")

  /** The value of the parameter `name`; an IllegalArgumentException if there is none. */
  def apply(name: String): Double =
    val i = names.indexOf(name)
    require(i >= 0, s"no parameter named '$name'; the parameters are ${names.mkString(", ")}")
    values(i)

  override def toString: String =
    names.lazyZip(values).map((n, v) => s"$n=$v").mkString(s"Row($index, seed $seed: ", ", ", ")")
