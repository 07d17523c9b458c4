package sims.sweep

import sims.dynamics.World

/** Many simulations of one scene: for each row of `parameters`, build a world, step it until
  * `stop`, and measure it with `metrics`; the result is a table of parameters and metrics.
  *
  * Every function here is run on whichever back end runs the sweep (on a Spark cluster, in
  * another JVM), so it must be serializable: functions that use only their arguments and
  * top-level objects are. A run depends on its row alone, so every back end gives the same
  * table, bit for bit.
  *
  * @param parameters the runs: a [[Grid]] or a [[RandomSample]]
  * @param build the scene of one run, from its row (its parameters and seed)
  * @param stop how many steps a run takes, or the condition that ends it
  * @param metrics what is measured from each world at its end
  * @param seed the sweep's seed, from which every row's seed (and a random sample's values) follow
  */
final case class Sweep(parameters: Parameters, build: Row => World, stop: Stop, metrics: Seq[Metric],
    seed: Long = 0L):
  private val columns = Seq("run", "seed") ++ parameters.names ++ Seq("steps") ++ metrics.map(_.name)
  private val repeated = columns.diff(columns.distinct)
  require(repeated.isEmpty, s"the table's column names must differ, got ${repeated.distinct.mkString(", ")} twice")

  /** Every run's row, in order. */
  def rows: IndexedSeq[Row] = parameters.rows(seed)

  /** Builds, steps and measures one run. */
  def runOne(row: Row): RunResult =
    val world = build(row)
    var steps = 0
    val done = stop.condition.getOrElse(Sweep.Never)
    while steps < stop.maxSteps && !done(world) do
      world.step()
      steps += 1
    RunResult(row, steps, metrics.map(_.measure(world)).toIndexedSeq)

  /** Runs every row on `backend` (all local cores unless told otherwise). */
  def run(backend: Backend = LocalBackend()): ResultTable =
    ResultTable(parameters.names, metrics.map(_.name).toIndexedSeq, backend.runAll(this))

  override def toString: String = s"Sweep($parameters, $stop, metrics ${metrics.map(_.name).mkString(", ")}, seed $seed)"

/** Helpers of sweeps. */
object Sweep:
  private val Never: World => Boolean = _ => false
