package sims.sweep

/** One column of a result table: whole numbers (a run's index, seed and steps) or real ones
  * (parameters and metrics).
  */
enum Column(val name: String):
  /** Whole numbers, 64-bit. */
  case Whole(override val name: String, values: IndexedSeq[Long]) extends Column(name)
  /** Real numbers, 64-bit floating point. */
  case Real(override val name: String, values: IndexedSeq[Double]) extends Column(name)

  /** The number of values. */
  def size: Int = this match
    case Whole(_, values) => values.size
    case Real(_, values) => values.size

  /** Value `i` as text: Long's and Double's own, which read back to the same number. */
  def text(i: Int): String = this match
    case Whole(_, values) => values(i).toString
    case Real(_, values) => values(i).toString
