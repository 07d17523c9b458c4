package sims.sweep

/** Where a sweep's runs are carried out: [[LocalBackend]] (this machine's cores) or
  * `sims.sweep.spark.SparkBackend` (a Spark cluster, or Spark in local mode).
  */
trait Backend:
  /** Every run of `sweep`, in the order of its rows. */
  def runAll(sweep: Sweep): IndexedSeq[RunResult]
