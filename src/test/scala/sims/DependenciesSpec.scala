package sims

import java.nio.file.{Files, Path, Paths}
import scala.jdk.CollectionConverters.*
import org.scalatest.funsuite.AnyFunSuite

/** Dependencies point one way: `geometry` uses nothing else of the library; `dynamics` (shapes,
  * bodies, joints, the world) and `collision` do not use the steps (`sims.solver`), except the
  * world's own reference to the solver it runs (the seam: `Solver`, and `ClassicStep`, the
  * default). Reads the library's sources.
  */
class DependenciesSpec extends AnyFunSuite:
  private val root = Paths.get("src/main/scala/sims")

  private def files(folder: String): Seq[Path] =
    val dir = root.resolve(folder)
    assert(Files.isDirectory(dir), s"no $dir: run the test from the repository's root")
    Files.walk(dir).iterator().asScala.filter(_.toString.endsWith(".scala")).toSeq.sorted

  /** The library packages a file's code refers to, in its imports and in qualified names (its
    * comments left out).
    */
  private def uses(file: Path): Set[String] =
    val code = Files.readAllLines(file).asScala.map(_.trim).filterNot(l =>
      l.startsWith("*") || l.startsWith("/*") ||
        l.startsWith("//"))
    val name = raw"\bsims\.(geometry|dynamics|collision|solver|prefabs|io)\b".r
    code.flatMap(line => name.findAllMatchIn(line).map(_.group(1))).toSet

  private def offenders(folder: String, forbidden: Set[String], except: Path => Boolean = _ => false): Seq[String] =
    for
      file <- files(folder) if !except(file)
      used = uses(file) intersect forbidden if used.nonEmpty
    yield s"$file uses ${used.mkString(", ")}"

  test("geometry uses no other package of the library"):
    val found = offenders("geometry", Set("dynamics", "collision", "solver", "prefabs", "io"))
    assert(found.isEmpty, found.mkString("\n"))

  test("dynamics and collision do not use the steps, but for the world's own solver"):
    val choice = root.resolve("dynamics/SolverChoice.scala")
    val found = offenders("dynamics", Set("solver", "prefabs", "io"), _ == choice) ++
      offenders("collision", Set("solver", "prefabs", "io"))
    assert(found.isEmpty, found.mkString("\n"))
    val choiceImports = Files.readAllLines(choice).asScala.filter(_.startsWith("import sims.solver"))
    assert(choiceImports == Seq("import sims.solver.{ClassicStep, Solver}"), choiceImports)

  test("the world only coordinates: World.scala stays under 250 lines, its parts in files of their own"):
    val lines = Files.readAllLines(root.resolve("dynamics/World.scala")).size
    assert(lines < 250, s"World.scala has $lines lines")

  test("the joints know neither the steps nor the world's other parts but the bodies"):
    val found = offenders("dynamics/joints", Set("solver", "collision", "prefabs", "io"))
    assert(found.isEmpty, found.mkString("\n"))
