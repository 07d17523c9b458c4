package sims.sweep.spark

import org.apache.spark.{SparkConf, SparkContext}
import sims.sweep.{Backend, RunResult, Sweep}

/** Runs a sweep on Spark: each run is one task, given its row (and so its seed) and nothing
  * else, so the table is the same as the local back end's whatever the cluster. The same code
  * runs with a `local[n]` master and on a cluster (through spark-submit, which sets the master).
  *
  * The sweep travels to the executors serialized, functions and all; the results come back to
  * the driver, a few numbers per run. Spark's classes are touched only here.
  *
  * @param context the Spark context; the caller starts and stops it
  */
final class SparkBackend(val context: SparkContext) extends Backend:
  def runAll(sweep: Sweep): IndexedSeq[RunResult] =
    val rows = sweep.rows
    if rows.isEmpty then IndexedSeq.empty
    else
      // One partition per run: each simulation is a task of its own.
      val results = context.parallelize(rows, rows.size).map(sweep.runOne).collect()
      // Partitions come back in order; sorting again costs little and states the contract.
      results.sortBy(_.row.index).toIndexedSeq

  override def toString: String = s"SparkBackend(${context.master})"

/** Spark contexts for sweeps. */
object SparkBackend:
  /** Starts a Spark context for `master` (`local[2]`, say; on spark-submit the master it was
    * given, whatever is passed here), runs `body` with a back end on it and stops it again.
    */
  def using[A](master: String, appName: String = "sims-sweep")(body: SparkBackend => A): A =
    val configuration = new SparkConf().setAppName(appName).setIfMissing("spark.master", master)
      // The driver's web page is of no use to a sweep; without it, no port is opened for it.
      .setIfMissing("spark.ui.enabled", "false")
    // In local mode every task runs in this JVM: the driver listens on the loopback address only.
    if configuration.get("spark.master").startsWith("local") then
      configuration.setIfMissing("spark.driver.bindAddress", "127.0.0.1").setIfMissing("spark.driver.host", "127.0.0.1")
    val context = SparkContext.getOrCreate(configuration)
    try body(SparkBackend(context))
    finally context.stop()
