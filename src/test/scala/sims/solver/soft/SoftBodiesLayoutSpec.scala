package sims.solver.soft

import java.nio.file.{Files, Path, Paths}
import scala.jdk.CollectionConverters.*
import org.scalatest.funsuite.AnyFunSuite

/** The soft step's body layout (`SoftBodies.state`) is named in one place, SoftBodies' companion:
  * every other file reads and writes the array through those names, so that reordering the
  * layout cannot silently break a joint or a contact in another file. Reads the library's sources.
  */
class SoftBodiesLayoutSpec extends AnyFunSuite:
  private val sources = Paths.get("src/main/scala")
  private val layoutFile = sources.resolve("sims/solver/soft/SoftBodies.scala")

  private def scalaFiles: Seq[Path] =
    Files.walk(sources).iterator().asScala.filter(_.toString.endsWith(".scala")).toSeq.sorted

  // An index into `state` without a named offset: `state(k)` or `state(k + 3)`.
  private val bareIndex = raw"\bstate\(\s*[A-Za-z_][A-Za-z0-9_]*\s*\)".r
  private val literalOffset = raw"\bstate\([^)]*\+\s*[0-9]".r

  test("the library's sources are where the test reads them"):
    assert(Files.isRegularFile(layoutFile), s"no $layoutFile: run the test from the repository's root")
    assert(scalaFiles.size > 50)

  test("no file but SoftBodies indexes the bodies' state with a literal offset"):
    val offenders =
      for
        file <- scalaFiles if file != layoutFile
        (line, number) <- Files.readAllLines(file).asScala.zipWithIndex
        if bareIndex.findFirstIn(line).isDefined || literalOffset.findFirstIn(line).isDefined
      yield s"$file:${number + 1}: ${line.trim}"
    assert(offenders.isEmpty, offenders.mkString("\n"))

  test("the offsets are named in SoftBodies and used elsewhere"):
    val layout = Files.readString(layoutFile)
    for name <- Seq("VelocityX", "VelocityY", "AngularVelocity", "ShiftX", "ShiftY", "Turn", "TurnCos", "TurnSin") do
      assert(layout.contains(s"inline val $name ="), name)
    val users = scalaFiles.filter(f => f != layoutFile && Files.readString(f).contains("+ TurnCos)"))
    assert(users.nonEmpty)

  test("the names give each value its own place"):
    import SoftBodies.*
    val offsets = Seq(VelocityX, VelocityY, AngularVelocity, ShiftX, ShiftY, Turn, TurnCos, TurnSin)
    assert(offsets.sorted == (0 until Stride))
