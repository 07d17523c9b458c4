package sims.sweep

import java.nio.charset.StandardCharsets
import java.nio.file.{Files, Path}

/** The result of a sweep: one row per run, with the columns `run` (its index), `seed`, one per
  * parameter, `steps` (taken before it stopped) and one per metric.
  *
  * @param parameterNames the parameters, in their columns' order
  * @param metricNames the metrics, in their columns' order
  * @param results every run's result, in the order of the runs
  */
final case class ResultTable(parameterNames: IndexedSeq[String], metricNames: IndexedSeq[String],
    results: IndexedSeq[RunResult]):
  results.zipWithIndex.foreach { (result, i) =>
    require(result.row.index == i, s"result $i is of run ${result.row.index}: results must be in the runs' order")
    require(result.row.names == parameterNames, s"run $i has parameters ${result.row.names}, not $parameterNames")
    require(result.metrics.size == metricNames.size, s"run $i has ${result.metrics.size} metrics, not ${metricNames.size}")
  }

  /** The number of runs. */
  def size: Int = results.size

  /** The columns, in order. */
  def columns: IndexedSeq[Column] =
    IndexedSeq(
      Column.Whole("run", results.map(_.row.index.toLong)),
      Column.Whole("seed", results.map(_.row.seed))
    ) ++ parameterNames.indices.map(k => Column.Real(parameterNames(k), results.map(_.row.values(k)))) ++
      IndexedSeq(Column.Whole("steps", results.map(_.steps.toLong))) ++
      metricNames.indices.map(k => Column.Real(metricNames(k), results.map(_.metrics(k))))

  /** The values of the parameter or metric `name`; an IllegalArgumentException if none has it. */
  def apply(name: String): IndexedSeq[Double] =
    val parameter = parameterNames.indexOf(name)
    val metric = metricNames.indexOf(name)
    require(parameter >= 0 || metric >= 0,
      s"no parameter or metric named '$name'; there are ${(parameterNames ++ metricNames).mkString(", ")}")
    if parameter >= 0 then results.map(_.row.values(parameter)) else results.map(_.metrics(metric))

  /** The table as CSV: a header line of the column names, then one line per run (`\n` ends every
    * line; numbers as Scala prints them, which read back to the same bits).
    */
  def toCsv: String =
    val all = columns
    val lines = Iterator(all.map(_.name).mkString(",")) ++
      results.indices.iterator.map(i => all.map(_.text(i)).mkString(","))
    lines.mkString("", "\n", "\n")

  /** Writes `toCsv` to `path` (UTF-8). */
  def writeCsv(path: Path): Unit = Files.write(path, toCsv.getBytes(StandardCharsets.UTF_8))

  /** Writes the table to `path` as a Parquet file (one row group, plain encoding, uncompressed). */
  def writeParquet(path: Path): Unit = Files.write(path, ParquetWriter.bytes(columns, size))

  override def toString: String =
    s"ResultTable($size runs; columns ${columns.map(_.name).mkString(", ")})"
