package sims.examples.headless

import java.io.{File, PrintStream}
import javax.imageio.ImageIO
import sims.examples.render.{GifWriter, RenderOptions, Renderer, Viewport}
import sims.scenes.Scene

/** Runs a scene without a window and writes what happened: an animated GIF, a PNG of the
  * last frame and a CSV of every body's state.
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

  /** Simulates `scene` for `seconds`, writing `<name>.gif`, `<name>.png`, `<name>.csv` into
    * `directory` (created if needed) and reporting progress on `out`.
    */
  def run(scene: Scene, seconds: Double, directory: File, out: PrintStream = System.out,
      interactive: Boolean = ProgressBar.stdoutIsTerminal): Result =
    require(seconds >= 0, s"seconds must be at least 0, got $seconds")
    directory.mkdirs()
    val base = scene.name.toLowerCase
    val gifFile = File(directory, s"$base.gif")
    val pngFile = File(directory, s"$base.png")
    val csvFile = File(directory, s"$base.csv")
    val staged = scene.build()
    val world = staged.world
    val viewport = Viewport.fit(scene.view, Width, Height)
    val totalSteps = math.round(seconds / world.timeStep)
    out.println(s"${scene.name}: ${scene.description}")
    out.println(s"${world.bodies.length} bodies, ${world.shapes.length} shapes, ${world.joints.length} joints; " +
      f"$seconds%.2f s = $totalSteps steps")
    val bar = ProgressBar(seconds, out, interactive)
    def picture(smooth: Boolean) =
      Renderer.image(world, viewport, RenderOptions(caption = f"${scene.name}  t = ${world.time}%.2f s", smooth = smooth),
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
