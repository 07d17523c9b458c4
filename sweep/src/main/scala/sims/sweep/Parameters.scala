package sims.sweep

/** The parameters of a sweep's runs: every combination of a grid's axes, a random sample, or a set of
  * a user's own (a row must depend on its index and the seed alone).
  */
trait Parameters extends Serializable:
  /** The parameters' names, in the table's order. */
  def names: IndexedSeq[String]

  /** The number of runs. */
  def size: Int

  /** Run `index`'s row in a sweep seeded with `seed`: a function of the two alone. */
  def row(index: Int, seed: Long): Row

  /** Every run's row, in order. */
  final def rows(seed: Long): IndexedSeq[Row] = IndexedSeq.tabulate(size)(row(_, seed))

  protected final def requireDistinct(): Unit =
    val repeated = names.diff(names.distinct)
    require(repeated.isEmpty, s"parameter names must differ, got ${repeated.distinct.mkString(", ")} more than once")

/** A grid: every combination of its axes' values, the last axis changing fastest.
  *
  * @param axes one axis per parameter, at least one
  */
final case class Grid(axes: Axis*) extends Parameters:
  require(axes.nonEmpty, "a grid needs at least one axis")
  val names: IndexedSeq[String] = axes.map(_.name).toIndexedSeq
  requireDistinct()
  private val total = axes.foldLeft(1L)(_ * _.values.size)
  require(total <= Int.MaxValue, s"a grid has at most ${Int.MaxValue} runs, got $total")
  val size: Int = total.toInt

  def row(index: Int, seed: Long): Row =
    require(index >= 0 && index < size, s"index is from 0 to ${size - 1}, got $index")
    val values = new Array[Double](axes.size)
    var rest = index
    var k = axes.size - 1
    while k >= 0 do
      val axis = axes(k).values
      values(k) = axis(rest % axis.size)
      rest /= axis.size
      k -= 1
    Row(index, Seeds.ofRun(seed, index), names, values.toIndexedSeq)

  override def toString: String = s"Grid(${axes.mkString(" x ")}: $size runs)"

/** A random sample: `count` runs, each parameter drawn uniformly from its interval, run `i`'s
  * values from its own seed (so that they do not depend on how runs are shared out).
  */
final case class RandomSample(count: Int, intervals: Interval*) extends Parameters:
  require(count >= 0, s"count must be at least 0, got $count")
  require(intervals.nonEmpty, "a random sample needs at least one interval")
  val names: IndexedSeq[String] = intervals.map(_.name).toIndexedSeq
  requireDistinct()
  def size: Int = count

  def row(index: Int, seed: Long): Row =
    require(index >= 0 && index < size, s"index is from 0 to ${size - 1}, got $index")
    val runSeed = Seeds.ofRun(seed, index)
    // The scene gets `runSeed`; the values come from a stream of their own (k from 1 on), so a
    // scene drawing from `runSeed` with k = 0, 1, ... does not repeat them.
    val values = intervals.indices.map(k => intervals(k).at(Seeds.uniform(~runSeed, k)))
    Row(index, runSeed, names, values)

  override def toString: String = s"RandomSample($count runs of ${intervals.mkString(", ")})"
