package sims.bench

import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import org.openjdk.jmh.profile.GCProfiler
import org.openjdk.jmh.results.RunResult
import org.openjdk.jmh.runner.Runner
import org.openjdk.jmh.runner.options.{OptionsBuilder, TimeValue}
import scala.jdk.CollectionConverters.*

/** Runs every scene in every engine (SiMS with the classic and with the soft step, jBox2D,
  * dyn4j) with the same JMH settings in one run, with the GC profiler, and writes a Markdown
  * table to `bench/results/<date>.md`.
  *
  * Arguments (all optional): scene names to run (default: all), `--forks N` (default 1),
  * `--iterations N` measurement iterations of 1 s (default 5), `--warmup N` warm-up iterations
  * of 1 s after the warm-up steps (default 3), `--out FILE` (relative to the repository's root),
  * `--box2d SCRIPT`: Box2D v3's build script (see [[Box2DPeer]]), run after the benchmarks, in the
  * same window, on the scenes it knows, its times in a second table.
  */
object RunAll:
  /** One engine's figures for one scene. */
  final case class Row(scene: String, engine: String, microseconds: Double, error: Double,
      bytesPerStep: Double, sanity: Option[(Boolean, Long, String)])

  def main(args: Array[String]): Unit =
    var forks = 1
    var iterations = 5
    var warmup = 3
    var out: Option[String] = None
    var box2dScript: Option[String] = None
    val scenes = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--forks" => forks = it.next().toInt
        case "--iterations" => iterations = it.next().toInt
        case "--warmup" => warmup = it.next().toInt
        case "--out" => out = Some(it.next())
        case "--box2d" => box2dScript = Some(it.next())
        case scene => scenes += scene
    // Cheap scenes first, so an interrupted run still has them.
    val chosen = Some(scenes.result()).filter(_.nonEmpty)
      .getOrElse(Settings.names.sortBy(n =>
          Settings.scene(n) match
            case pit: sims.scenes.Ballpit => pit.balls
            case _ => 0))
    val sanityFile = Files.createTempFile("sims-bench-sanity", ".tsv")
    val started = System.nanoTime()
    val results = chosen.flatMap { scene =>
      val options = OptionsBuilder()
        .include(classOf[StepBenchmark].getName + ".step$")
        .param("scene", scene)
        .param("engine", Engine.forScene(Settings.scene(scene)).map(_.label)*)
        .forks(forks)
        .warmupIterations(warmup).warmupTime(TimeValue.seconds(1))
        .measurementIterations(iterations).measurementTime(TimeValue.seconds(1))
        .timeUnit(TimeUnit.MICROSECONDS)
        .addProfiler(classOf[GCProfiler])
        .jvmArgsAppend("-Xmx3g", s"-Dsims.bench.sanity=$sanityFile")
        .build()
      Runner(options).run().asScala.toSeq
    }
    // sbt forks the run in bench/; paths are taken relative to the repository's root.
    val root = if Files.isDirectory(Path.of("bench/results")) then Path.of(".") else Path.of("..")
    val box2d = box2dScript.map(script => Box2DPeer.measure(root.resolve(script), chosen)).getOrElse(Map.empty)
    val minutes = (System.nanoTime() - started) / 6e10
    val sanity = Files.readAllLines(sanityFile).asScala.map(_.split("\t", 5)).map(a =>
      (a(0), a(1)) -> (a(2).toBoolean, a(3).toLong, a(4))).toMap
    val rows = results.map(row(_, sanity))
    val date = java.time.LocalDate.now().toString
    val file = root.resolve(out.getOrElse(s"bench/results/$date.md"))
    val text = Report.markdown(rows, box2d, date, forks, warmup, iterations, minutes)
    Files.writeString(file, text)
    println(text)
    println(s"written to ${file.toAbsolutePath}")

  private def row(r: RunResult, sanity: Map[(String, String), (Boolean, Long, String)]): Row =
    val engine = r.getParams.getParam("engine")
    val scene = r.getParams.getParam("scene")
    val primary = r.getPrimaryResult
    val allocation = r.getSecondaryResults.asScala.collectFirst {
      case (key, value) if key.endsWith("gc.alloc.rate.norm") => value.getScore
    }.getOrElse(Double.NaN)
    Row(scene, engine, primary.getScore, primary.getScoreError, allocation, sanity.get((engine, scene)))
