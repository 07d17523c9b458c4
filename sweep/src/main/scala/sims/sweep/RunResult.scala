package sims.sweep

/** What one run gave: its row, the steps it took and each metric's value.
  *
  * @param metrics in the order of the sweep's metrics
  */
final case class RunResult(row: Row, steps: Int, metrics: IndexedSeq[Double])
