package sims.bench

import java.nio.file.{Files, Path}
import scala.sys.process.*

/** Box2D v3 (C, one thread), measured by the caller's copy of its build script in the same run
  * as the JMH benchmarks: the bench's own scenes (`ballpit-N`, `pyramid-R`, `chain-N`) through the
  * script's `run` (the scenes written with Box2D's API: 300 warm-up steps, then the median of 600
  * timed steps), Box2D's benchmark scenes (`large_pyramid`, `many_pyramids`, `joint_grid`,
  * `smash`, `rain`) through its `benchmark` (Box2D's own program, one worker: the fastest of its
  * runs over its steps, from the scene as built). Not part of the library or its build: the
  * script comes from outside the repository (`RunAll --box2d`).
  */
object Box2DPeer:
  /** The scenes Box2D's own benchmark program has, by the bench's names. */
  val BenchmarkScenes: Set[String] = Set("large_pyramid", "many_pyramids", "joint_grid", "smash", "rain")

  private val LayoutFamily = "(ballpit|pyramid|chain)-[0-9]+".r
  private val SummaryRow = raw"\|\s*(\S+)\s*\|\s*box2d-v3\s*\|\s*([0-9.]+)\s*\|.*".r
  private val Steps = raw"benchmark: \S+, steps = ([0-9]+)".r
  private val Run = raw"run [0-9]+ : ([0-9.]+) \(ms\)".r

  /** Whether Box2D can run this scene of the bench. */
  def knows(scene: String): Boolean = scene match
    case LayoutFamily(_) => true
    case other => BenchmarkScenes(other)

  /** Milliseconds per step of each scene it knows, measured by the script at `script`. */
  def measure(script: Path, scenes: Seq[String]): Map[String, Double] =
    require(Files.isExecutable(script), s"--box2d must name Box2D v3's build script, got $script")
    val layouts = scenes.filter(s => knows(s) && !BenchmarkScenes(s))
    val fromScenes =
      if layouts.isEmpty then Map.empty[String, Double]
      else
        val out = Seq(script.toString, "run", "--scenes", layouts.mkString(","), "--reps", "1").!!
        // The summary's rows (median ms per step), not the detailed tables after it.
        val summary = out.linesIterator.dropWhile(!_.startsWith("## Summary")).drop(1).takeWhile(!_.startsWith("## "))
        summary.collect { case SummaryRow(scene, ms) if layouts.contains(scene) => scene -> ms.toDouble }.toMap
    val fromBenchmark = scenes.filter(BenchmarkScenes).flatMap { scene =>
      val out = Seq(script.toString, "benchmark", "-t=1", "-w=1", s"--benchmark=$scene").!!
      val steps = out.linesIterator.collectFirst { case Steps(n) => n.toInt }
      val runs = out.linesIterator.collect { case Run(ms) => ms.toDouble }.toSeq
      steps.filter(_ => runs.nonEmpty).map(n => scene -> runs.min / n)
    }.toMap
    fromScenes ++ fromBenchmark
