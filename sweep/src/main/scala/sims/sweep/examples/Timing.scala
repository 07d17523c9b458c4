package sims.sweep.examples

import sims.dynamics.World
import sims.sweep.{Backend, Grid, LocalBackend, Metric, RandomSample, Interval, Stop, Sweep}
import sims.sweep.spark.SparkBackend

/** Runs per second of the Cannon sweep on each back end with 1 and 2 cores, and Spark's cost
  * per task (`sweep/runMain sims.sweep.examples.Timing [runs] [rounds]`). Each measurement is
  * the best of `rounds` after one round to warm up; whole sweeps are timed, so the numbers
  * include each back end's own costs (threads, tasks, serialization), which is the point.
  */
object Timing:
  /** Runs the measurements and prints a table. */
  def main(arguments: Array[String]): Unit =
    val runs = arguments.headOption.map(_.toInt).getOrElse(200)
    val rounds = arguments.lift(1).map(_.toInt).getOrElse(3)
    // The first `runs` runs of an evenly thinned grid: all speeds, materials spread.
    val sweep = CannonSweep.sweep().copy(parameters = Thinned(CannonSweep.parameters, runs))
    // A run that does nothing: what a back end costs per run, apart from the simulation.
    val empty = Sweep(RandomSample(runs, Interval("x", 0, 1)), _ => World(), Stop.after(0), Seq(Metric("t", _.time)))

    def best(backend: Backend, of: Sweep): Double =
      of.run(backend)
      (1 to rounds).map { _ =>
        val start = System.nanoTime
        of.run(backend)
        (System.nanoTime - start) / 1e9
      }.min

    val results = Seq.newBuilder[(String, Double, Double)]
    for threads <- Seq(1, 2) do
      val backend = LocalBackend(threads)
      results += ((s"local back end, $threads thread(s)", best(backend, sweep), best(backend, empty)))
    for threads <- Seq(1, 2) do
      SparkBackend.using(s"local[$threads]") { backend =>
        backend.context.setLogLevel("WARN")
        results += ((s"Spark local[$threads]", best(backend, sweep), best(backend, empty)))
      }
    println(f"$runs runs of ${CannonSweep.Steps} steps each; best of $rounds rounds")
    println(f"${"back end"}%-30s ${"runs/s"}%8s ${"ms/run"}%8s ${"empty runs: µs/run"}%20s")
    for (name, seconds, emptySeconds) <- results.result() do
      println(f"$name%-30s ${runs / seconds}%8.1f ${seconds / runs * 1e3}%8.2f ${emptySeconds / runs * 1e6}%20.1f")

/** The runs of `grid` at `count` evenly spread indices: a smaller sweep of the same scene. */
final case class Thinned(grid: Grid, count: Int) extends sims.sweep.Parameters:
  require(count >= 1 && count <= grid.size, s"count is from 1 to ${grid.size}, got $count")
  def names: IndexedSeq[String] = grid.names
  def size: Int = count
  def row(index: Int, seed: Long): sims.sweep.Row =
    grid.row((index.toLong * grid.size / count).toInt, seed).copy(index = index)
