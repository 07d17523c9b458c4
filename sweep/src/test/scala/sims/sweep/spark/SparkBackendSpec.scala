package sims.sweep.spark

import java.nio.file.Files
import org.apache.spark.sql.SparkSession
import org.scalatest.funsuite.AnyFunSuite
import sims.sweep.{Axis, Grid, LocalBackend}
import sims.sweep.examples.CannonSweep

/** Spark in local mode, in the forked test JVM (Spark's --add-opens in build.sbt). */
class SparkBackendSpec extends AnyFunSuite:
  // 12 runs of the example's scene, a second each: the shot reaches the pyramid within it.
  private val sweep = CannonSweep.sweep(Grid(
      Axis.evenly("speed", 8, 20, 3), Axis.evenly("restitution", 0, 0.8, 2), Axis.evenly("friction", 0.3, 0.9, 2)))
    .copy(stop = sims.sweep.Stop.after(60))
  private lazy val local = sweep.run(LocalBackend(2))

  test("local[1], local[2] and the local back end give the same table, bit for bit"):
    val one = SparkBackend.using("local[1]")(sweep.run(_))
    val two = SparkBackend.using("local[2]")(sweep.run(_))
    assert(one == local)
    assert(two == local)
    assert(two.toCsv == local.toCsv)
    // The metrics differ between runs, so a mix-up of rows would show.
    assert(local("ballX").distinct.size == local.size)

  test("Spark's Parquet reader reads the sweep's Parquet file back to the same numbers"):
    val file = Files.createTempFile("sweep", ".parquet")
    try
      local.writeParquet(file)
      val session = SparkSession.builder().master("local[1]").config("spark.ui.enabled", "false")
        .config("spark.driver.bindAddress", "127.0.0.1").config("spark.driver.host", "127.0.0.1").getOrCreate()
      try
        val frame = session.read.parquet(file.toString)
        assert(frame.columns.toSeq == local.columns.map(_.name))
        assert(frame.schema.fields.map(_.dataType.typeName).toSeq ==
          Seq("long", "long", "double", "double", "double", "long", "double", "double"))
        val rows = frame.collect().sortBy(_.getLong(0))
        assert(rows.length == local.size)
        for (row, i) <- rows.zipWithIndex do
          val result = local.results(i)
          assert(row.getLong(0) == i && row.getLong(1) == result.row.seed && row.getLong(5) == result.steps)
          assert((2 to 4).map(row.getDouble) == result.row.values)
          assert((6 to 7).map(row.getDouble) == result.metrics)
      finally session.stop()
    finally Files.delete(file)

  test("an empty sweep gives an empty table on Spark too, and a Parquet file without rows reads"):
    val none = sweep.copy(parameters = sims.sweep.RandomSample(0, sims.sweep.Interval("speed", 1, 2)))
    val table = SparkBackend.using("local[1]")(none.run(_))
    assert(table.size == 0)
    val file = Files.createTempFile("empty", ".parquet")
    try
      table.writeParquet(file)
      val session = SparkSession.builder().master("local[1]").config("spark.ui.enabled", "false")
        .config("spark.driver.bindAddress", "127.0.0.1").config("spark.driver.host", "127.0.0.1").getOrCreate()
      try assert(session.read.parquet(file.toString).count() == 0)
      finally session.stop()
    finally Files.delete(file)
