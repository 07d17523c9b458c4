package sims.bench

import java.io.File
import java.lang.reflect.Method
import java.net.URLClassLoader
import java.nio.file.{Files, Path}
import scala.collection.mutable.ArrayBuffer

/** Compares builds of SiMS on one scene by stepping them in turn in one JVM: a few percent
  * shows here where JMH runs minutes apart on a shared machine differ by more than that.
  *
  * Each build is a file holding its classpath, as `./sbt "export bench/Runtime/fullClasspath"`
  * prints it (in a work tree of the commit: `git worktree add`). Every build is loaded by a class
  * loader of its own, builds the scene, steps it through the bench's warm-up, and then the builds
  * take turns: `steps` steps each, timed, for `seconds` seconds (the first quarter, at most 10 s,
  * not counted). The report gives each build's minimum, 10th percentile and median µs per step,
  * and the median of its per-turn ratios to the first build's time in the same turn.
  *
  * The place in the turn has a bias of a few percent; run twice, with the builds in reverse
  * order, and take r = sqrt(ratio1 / ratio2) for B against A (ratio1 from A B, ratio2 from B A).
  *
  * Arguments: scene, engine label (as `Engine.named` takes it), seconds, steps per turn, then
  * two or more classpath files.
  */
object Alternate:
  /** One build under comparison: its scene, and the times of its turns in µs per step. */
  private final class Build(val name: String, val scene: AnyRef, val step: Method):
    val times = ArrayBuffer.empty[Double]

  def main(args: Array[String]): Unit =
    require(args.length >= 6, "usage: Alternate scene engine seconds steps classpathA classpathB [classpath...]")
    val (scene, engine) = (args(0), args(1))
    val seconds = args(2).toDouble
    val steps = args(3).toInt
    require(seconds > 0 && steps > 0, s"seconds and steps must be positive, got $seconds and $steps")
    val builds = args.drop(4).toSeq.map(load(_, scene, engine))
    val started = System.nanoTime()
    val counted = started + (math.min(10.0, seconds / 4) * 1e9).toLong
    val end = started + (seconds * 1e9).toLong
    while System.nanoTime() < end do
      val counting = System.nanoTime() > counted
      for build <- builds do
        val t0 = System.nanoTime()
        var i = 0
        while i < steps do
          build.step.invoke(build.scene)
          i += 1
        val time = (System.nanoTime() - t0) / 1e3 / steps
        if counting then build.times += time
    val first = builds.head
    for build <- builds do
      val sorted = build.times.sorted
      val turns = math.min(build.times.length, first.times.length)
      val ratios = (0 until turns).map(i => build.times(i) / first.times(i)).sorted
      println(f"${build.name}%-32s turns ${sorted.length}%5d  min ${sorted.head}%9.1f  p10 ${sorted(sorted.length / 10)}%9.1f  " +
        f"median ${sorted(sorted.length / 2)}%9.1f  median ratio to first ${ratios(turns / 2)}%.4f")

  /** Loads a build from its classpath file and runs the bench's warm-up steps of the scene. */
  private def load(classpathFile: String, scene: String, engine: String): Build =
    val urls = Files.readString(Path.of(classpathFile)).trim.split(File.pathSeparator).map(p => File(p).toURI.toURL)
    val loader = URLClassLoader(urls, ClassLoader.getPlatformClassLoader)
    val engineValue = loader.loadClass("sims.bench.Engine").getMethod("named", classOf[String]).invoke(null, engine)
    val sceneValue = loader.loadClass("sims.bench.Settings").getMethod("scene", classOf[String]).invoke(null, scene)
    val build = engineValue.getClass.getMethods.find(m => m.getName == "build" && m.getParameterCount == 1)
      .getOrElse(throw IllegalArgumentException(s"$classpathFile: its Engine has no build method"))
    val built = build.invoke(engineValue, sceneValue)
    val step = loader.loadClass("sims.bench.EngineScene").getMethod("step")
    val warmUp = loader.loadClass("sims.bench.Settings").getMethod("WarmUpSteps").invoke(null).asInstanceOf[Int]
    for _ <- 0 until warmUp do step.invoke(built)
    Build(classpathFile, built, step)
