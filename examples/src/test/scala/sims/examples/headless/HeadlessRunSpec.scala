package sims.examples.headless

import java.io.{ByteArrayOutputStream, PrintStream}
import java.nio.file.Files
import javax.imageio.ImageIO
import java.awt.image.BufferedImage
import org.scalatest.funsuite.AnyFunSuite
import sims.examples.SolverChoice
import sims.scenes.{Car, Spring, Stacking}

/** The main job's files: GIF, PNG and CSV of a short run, and the progress bar's two modes. */
class HeadlessRunSpec extends AnyFunSuite:
  test("a short run writes a GIF, a PNG of the last frame and a CSV of every body"):
    val directory = Files.createTempDirectory("sims-run").toFile
    val log = ByteArrayOutputStream()
    val result = HeadlessRun.run(Spring, 0.4, directory, PrintStream(log), interactive = false)
    assert(result.steps == 24)
    assert(result.gif.getName == "spring.gif" && result.gif.length > 0)
    // Frames at t = 0, 0.04, ..., 0.4: 11 of them.
    assert(result.frames == 11)
    val png = ImageIO.read(result.png)
    assert(png.getWidth == HeadlessRun.Width && png.getHeight == HeadlessRun.Height)
    val lines = scala.io.Source.fromFile(result.csv).getLines().toVector
    assert(lines.head == TrajectoryCsv.Header)
    // Samples at t = 0, 1/30, ..., 0.4 (13 of them), 2 bodies each.
    assert(lines.size == 1 + 13 * 2 && result.rows == 26)
    val last = lines.last.split(',')
    assert(last.length == 8 && last(1) == "1" && math.abs(last(0).toDouble - 0.4) < 1e-9)
    assert(last.drop(2).forall(_.toDouble.isFinite))
    val text = log.toString
    assert(text.contains("steps/s") && text.contains("wrote"))
    assert(!text.contains("\r"), "no carriage returns when the output is not a terminal")

  test("a run with the soft step says so and names its files after it"):
    val directory = Files.createTempDirectory("sims-run").toFile
    val log = ByteArrayOutputStream()
    val result = HeadlessRun.run(Spring, 0.2, directory, PrintStream(log), interactive = false, solver = SolverChoice.Soft)
    assert(result.steps == 12)
    assert(Seq(result.gif, result.png, result.csv).map(_.getName) == Seq("spring-soft.gif", "spring-soft.png", "spring-soft.csv"))
    assert(log.toString.contains("Solver: soft step (SoftStep("))

  test("a scene that runs under the soft step only runs with it; the classic step and a comparison are refused"):
    val directory = Files.createTempDirectory("sims-run").toFile
    val quiet = PrintStream(ByteArrayOutputStream())
    val result = HeadlessRun.run(Car, 0.2, directory, quiet, interactive = false, solver = SolverChoice.Soft)
    assert(result.steps == 12 && result.gif.getName == "car-soft.gif")
    val classic = intercept[IllegalArgumentException](HeadlessRun.run(Car, 0.2, directory, quiet, interactive = false))
    assert(classic.getMessage == "solver must be Soft for Car, which runs under the soft step only, got Classic")
    val compared = intercept[IllegalArgumentException](HeadlessRun.compare(Car, 0.2, directory, quiet, interactive = false))
    assert(compared.getMessage.contains("Car runs under the soft step only"))
    assert(!java.io.File(directory, "car.gif").exists && !java.io.File(directory, "car-compare.gif").exists)

  test("a comparison draws the classic step on the left and the soft step on the right of one GIF and PNG"):
    val directory = Files.createTempDirectory("sims-compare").toFile
    val log = ByteArrayOutputStream()
    val comparison = HeadlessRun.compare(Stacking, 0.4, directory, PrintStream(log), interactive = false)
    assert(comparison.steps == 24 && comparison.frames == 11)
    assert(comparison.gif.getName == "stacking-compare.gif" && comparison.gif.length > 0)
    assert(comparison.png.getName == "stacking-compare.png")
    val picture = ImageIO.read(comparison.png)
    assert(picture.getWidth == 2 * HeadlessRun.Width && picture.getHeight == HeadlessRun.Height)
    assert(log.toString.contains("classic step") && log.toString.contains("soft step"))
    // Each half is what a run with that solver alone draws, below the captions and beside the dividing line.
    val quiet = PrintStream(ByteArrayOutputStream())
    val classic = ImageIO.read(HeadlessRun.run(Stacking, 0.4, directory, quiet, interactive = false).png)
    val soft = ImageIO.read(HeadlessRun.run(Stacking, 0.4, directory, quiet, interactive = false, solver = SolverChoice.Soft).png)
    def differing(half: BufferedImage, offset: Int): Int =
      (for
        y <- 30 until HeadlessRun.Height; x <- 2 until HeadlessRun.Width - 2
        if half.getRGB(x, y) != picture.getRGB(offset + x, y)
      yield 1).size
    assert(differing(classic, 0) == 0)
    assert(differing(soft, HeadlessRun.Width) == 0)
    assert(differing(classic, HeadlessRun.Width) > 0, "the two solvers stack the boxes differently")

  test("the progress bar redraws in place on a terminal and prints at most 11 lines otherwise"):
    val plain = ByteArrayOutputStream()
    val bar = ProgressBar(1.0, PrintStream(plain), interactive = false)
    for i <- 1 to 60 do bar.update(i / 60.0, i, i * 1000000L)
    bar.finish()
    val lines = plain.toString.linesIterator.toVector
    assert(lines.size <= 11 && lines.last.contains("1.00 / 1.00 s"))
    val terminal = ByteArrayOutputStream()
    val live = ProgressBar(1.0, PrintStream(terminal), interactive = true)
    live.update(1.0, 60, 60000000L)
    live.finish()
    assert(terminal.toString.startsWith("\r[") && terminal.toString.contains("1000 steps/s"))
