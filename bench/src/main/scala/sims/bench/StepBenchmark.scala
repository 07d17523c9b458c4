package sims.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import scala.compiletime.uninitialized

/** Time of one step of a scene in one engine, after [[Settings.WarmUpSteps]] steps. The scene is
  * built once per fork and keeps running through warm-up and measurement; when the fork exits,
  * its sanity is checked and appended to the file named by the `sims.bench.sanity` property.
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MICROSECONDS)
class StepBenchmark:
  /** Engine label: SiMS (the classic step), SiMS-soft (the soft step), jBox2D or dyn4j. */
  @Param(Array("SiMS"))
  var engine: String = uninitialized

  /** Scene name, one of [[Settings.names]] (or any of `sims.scenes.Scenes.find`, in SiMS). */
  @Param(Array("ballpit-500"))
  var scene: String = uninitialized

  private var built: EngineScene = uninitialized
  private var steps = 0L

  /** Builds the scene and runs the warm-up steps. */
  @Setup(Level.Trial)
  def setup(): Unit =
    built = Engine.named(engine).build(Settings.scene(scene))
    var i = 0
    while i < Settings.WarmUpSteps do
      built.step()
      i += 1
    steps = Settings.WarmUpSteps

  /** One step. */
  @Benchmark
  def step(): Unit =
    built.step()
    steps += 1

  /** Checks the scene after the run and reports it. The check runs when the fork's JVM exits,
    * after JMH has taken its last measurement: run in a tear-down, its copies of the bodies'
    * states fell inside the gc profiler's last iteration and showed as allocation per step.
    */
  @TearDown(Level.Trial)
  def checkSanityAtExit(): Unit =
    Runtime.getRuntime.addShutdownHook(Thread(() => checkSanity()))

  private def checkSanity(): Unit =
    val result = Sanity.check(Settings.scene(scene), built)
    val line = s"$engine\t$scene\t${result.ok}\t$steps\t${result.detail}\n"
    Option(System.getProperty("sims.bench.sanity")) match
      case Some(file) =>
        java.nio.file.Files.writeString(java.nio.file.Path.of(file), line,
          java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.APPEND)
      case None => print(line)
