package sims.sweep

import java.util.concurrent.{Executors, TimeUnit}
import java.util.concurrent.atomic.AtomicInteger

/** Runs a sweep on this machine's cores: `threads` threads take the next run not yet taken
  * until none is left. Each result goes to its run's place, so the table does not depend on
  * the number of threads or on which thread ran what.
  *
  * @param threads at least 1; all the processors the JVM sees unless told otherwise
  */
final case class LocalBackend(threads: Int = Runtime.getRuntime.availableProcessors) extends Backend:
  require(threads >= 1, s"threads must be at least 1, got $threads")

  /** Every run of `sweep`; if runs fail, a [[RunFailedException]] for the first of them (the
    * others still run, so that which one is reported does not depend on the threads' timing).
    */
  def runAll(sweep: Sweep): IndexedSeq[RunResult] =
    val rows = sweep.rows
    val results = new Array[RunResult](rows.size)
    val failures = new Array[Throwable](rows.size)
    val next = AtomicInteger(0)
    val work: Runnable = () =>
      var i = next.getAndIncrement()
      while i < rows.size do
        try results(i) = sweep.runOne(rows(i))
        catch case error: Exception => failures(i) = error
        i = next.getAndIncrement()
    if threads == 1 then work.run()
    else
      val pool = Executors.newFixedThreadPool(threads)
      try
        for _ <- 0 until threads do pool.execute(work)
        pool.shutdown()
        while !pool.awaitTermination(1, TimeUnit.MINUTES) do ()
      finally pool.shutdownNow()
    val failed = failures.indexWhere(_ != null)
    if failed >= 0 then throw RunFailedException(rows(failed), failures(failed))
    results.toIndexedSeq

  override def toString: String = s"LocalBackend($threads threads)"
