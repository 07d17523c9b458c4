package sims.examples.headless

import java.io.{ByteArrayOutputStream, PrintStream}
import java.nio.file.Files
import javax.imageio.ImageIO
import org.scalatest.funsuite.AnyFunSuite
import sims.scenes.Spring

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
