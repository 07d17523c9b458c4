package sims.examples.headless

import java.io.{File, PrintStream}
import javax.imageio.ImageIO
import sims.dynamics.World
import sims.examples.SolverChoice
import sims.examples.render.{GifWriter, RenderOptions, Renderer, SideBySide, Viewport}
import sims.scenes.Scene

/** Runs a scene without a window and writes what happened: an animated GIF, a PNG of the
  * last frame and a CSV of every body's state; or, to compare the solvers, the scene under
  * both side by side in one GIF and one PNG.
  */
object HeadlessRun:
  /** GIF frames per simulated second. */
  val FramesPerSecond = 25
  /** CSV samples per simulated second. */
  val SamplesPerSecond = 30
  /** Picture width, pixels. */
  val Width = 480
  /** Picture height, pixels. */
  val Height = 360

  /** What a run produced. */
  final case class Result(gif: File, png: File, csv: File, steps: Long, stepNanos: Long, frames: Int, rows: Long):
    /** Mean wall time of one step, ms. */
    def millisPerStep: Double = if steps == 0 then 0 else stepNanos / 1e6 / steps

    /** Steps per second of wall time (stepping only, drawing and writing excluded). */
    def stepsPerSecond: Double = if stepNanos == 0 then 0 else steps * 1e9 / stepNanos

  /** What a comparison produced: the side-by-side GIF and PNG, and each solver's stepping time. */
  final case class Comparison(gif: File, png: File, steps: Long, classicNanos: Long, softNanos: Long, frames: Int):
    /** Mean wall time of one classic step, ms. */
    def classicMillisPerStep: Double = if steps == 0 then 0 else classicNanos / 1e6 / steps

    /** Mean wall time of one soft step, ms. */
    def softMillisPerStep: Double = if steps == 0 then 0 else softNanos / 1e6 / steps

  /** The base of a run's file names: the scene's name in lower case, `-soft` added for the soft step. */
  def baseName(scene: Scene, solver: SolverChoice): String = solver match
    case SolverChoice.Classic => scene.name.toLowerCase
    case SolverChoice.Soft => s"${scene.name.toLowerCase}-soft"

  /** Simulates `scene` for `seconds` with `solver`, writing `<name>.gif`, `<name>.png`,
    * `<name>.csv` into `directory` (created if needed; the name ends in `-soft` for the soft
    * step) and reporting progress on `out`. A scene that runs under the soft step only needs
    * `solver` Soft.
    */
  def run(scene: Scene, seconds: Double, directory: File, out: PrintStream = System.out,
      interactive: Boolean = ProgressBar.stdoutIsTerminal, solver: SolverChoice = SolverChoice.Classic): Result =
    require(seconds >= 0, s"seconds must be at least 0, got $seconds")
    if !SolverChoice.offeredFor(scene).contains(solver) then
      throw IllegalArgumentException(s"solver must be Soft for ${scene.name}, which runs under the soft step only, got $solver")
    directory.mkdirs()
    val base = baseName(scene, solver)
    val gifFile = File(directory, s"$base.gif")
    val pngFile = File(directory, s"$base.png")
    val csvFile = File(directory, s"$base.csv")
    val staged = scene.build()
    val world = staged.world
    world.solver = solver.solver
    val viewport = Viewport.fit(scene.view, Width, Height)
    val totalSteps = math.round(seconds / world.timeStep)
    describe(scene, world, seconds, totalSteps, out)
    out.println(s"Solver: ${solver.label} (${world.solver})")
    val bar = ProgressBar(seconds, out, interactive)
    // The classic step's captions stay as they always were; the soft step's say so.
    val named = if solver == SolverChoice.Classic then "" else s"  (${solver.label})"
    def picture(smooth: Boolean) =
      Renderer.image(world, viewport, RenderOptions(caption = f"${scene.name}  t = ${world.time}%.2f s$named", smooth = smooth),
        staged.overlay())
    var steps = 0L
    var stepNanos = 0L
    var nextFrame = 0
    var nextSample = 0
    val csv = TrajectoryCsv(csvFile)
    // GIF frames are drawn in the renderer's own colours only, so they stay exact and small.
    val gif = GifWriter(gifFile, 1000 / FramesPerSecond, Renderer.colours)
    try
      // Frames and samples are taken when the simulated time reaches their due time.
      def record(): Unit =
        val epsilon = world.timeStep / 2
        while nextFrame.toDouble / FramesPerSecond <= world.time + epsilon do
          gif.write(picture(smooth = false))
          nextFrame += 1
        while nextSample.toDouble / SamplesPerSecond <= world.time + epsilon do
          csv.sample(world)
          nextSample += 1
      record()
      while steps < totalSteps do
        val start = System.nanoTime()
        world.step()
        stepNanos += System.nanoTime() - start
        steps += 1
        record()
        bar.update(world.time, steps, stepNanos)
      bar.update(world.time, steps, stepNanos)
      bar.finish()
    finally
      gif.close()
      csv.close()
    ImageIO.write(picture(smooth = true), "png", pngFile)
    val result = Result(gifFile, pngFile, csvFile, steps, stepNanos, gif.frames, csv.rowCount)
    out.println(f"${result.stepsPerSecond}%.0f steps/s, ${result.millisPerStep}%.3f ms/step; wrote ${gifFile.getPath} " +
      s"(${result.frames} frames), ${pngFile.getPath}, ${csvFile.getPath} (${result.rows} rows)")
    result

  /** Simulates `scene` for `seconds` twice in lockstep, one world with the classic step and
    * one with the soft step, and writes `<name>-compare.gif` and `<name>-compare.png` into `directory`: the
    * classic step on the left, the soft step on the right, each labelled. Not for a scene that
    * runs under the soft step only.
    */
  def compare(scene: Scene, seconds: Double, directory: File, out: PrintStream = System.out,
      interactive: Boolean = ProgressBar.stdoutIsTerminal): Comparison =
    require(seconds >= 0, s"seconds must be at least 0, got $seconds")
    if scene.softStepOnly then
      throw IllegalArgumentException(s"scene ${scene.name} runs under the soft step only: it has nothing to compare")
    directory.mkdirs()
    val base = s"${scene.name.toLowerCase}-compare"
    val gifFile = File(directory, s"$base.gif")
    val pngFile = File(directory, s"$base.png")
    val classic = scene.build().world
    val soft = scene.build().world
    classic.solver = SolverChoice.Classic.solver
    soft.solver = SolverChoice.Soft.solver
    val viewport = Viewport.fit(scene.view, Width, Height)
    val totalSteps = math.round(seconds / classic.timeStep)
    describe(scene, classic, seconds, totalSteps, out)
    out.println(s"Solvers: ${SolverChoice.Classic.label} (left), ${SolverChoice.Soft.label} (right, ${soft.solver})")
    val bar = ProgressBar(seconds, out, interactive)
    def picture(smooth: Boolean) =
      def caption(world: World, solver: SolverChoice) = f"${scene.name}  ${solver.label}  t = ${world.time}%.2f s"
      SideBySide.image(classic, soft, viewport, caption(classic, SolverChoice.Classic), caption(soft, SolverChoice.Soft),
        smooth)
    var steps = 0L
    var classicNanos = 0L
    var softNanos = 0L
    var nextFrame = 0
    val gif = GifWriter(gifFile, 1000 / FramesPerSecond, Renderer.colours)
    try
      def record(): Unit =
        while nextFrame.toDouble / FramesPerSecond <= classic.time + classic.timeStep / 2 do
          gif.write(picture(smooth = false))
          nextFrame += 1
      record()
      while steps < totalSteps do
        val start = System.nanoTime()
        classic.step()
        val middle = System.nanoTime()
        soft.step()
        classicNanos += middle - start
        softNanos += System.nanoTime() - middle
        steps += 1
        record()
        bar.update(classic.time, steps, classicNanos + softNanos)
      bar.update(classic.time, steps, classicNanos + softNanos)
      bar.finish()
    finally gif.close()
    ImageIO.write(picture(smooth = true), "png", pngFile)
    val result = Comparison(gifFile, pngFile, steps, classicNanos, softNanos, gif.frames)
    out.println(f"classic step ${result.classicMillisPerStep}%.3f ms/step, soft step ${result.softMillisPerStep}%.3f ms/step; " +
      s"wrote ${gifFile.getPath} (${result.frames} frames), ${pngFile.getPath}")
    result

  private def describe(scene: Scene, world: World, seconds: Double, totalSteps: Long, out: PrintStream): Unit =
    out.println(s"${scene.name}: ${scene.description}")
    out.println(s"${world.bodies.length} bodies, ${world.shapes.length} shapes, ${world.joints.length} joints; " +
      f"$seconds%.2f s = $totalSteps steps")
