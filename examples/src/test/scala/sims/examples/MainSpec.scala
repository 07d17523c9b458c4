package sims.examples

import java.io.File
import org.scalatest.funsuite.AnyFunSuite
import sims.scenes.Scenes

/** The command line. */
class MainSpec extends AnyFunSuite:
  import Main.{Options, parse}

  test("no arguments: the default options"):
    assert(parse(Nil) == Right(Options()))

  test("a scene with seconds and an output directory"):
    assert(parse(Seq("Chain", "--seconds", "2", "--out", "tmp")) ==
      Right(Options(scene = Some("Chain"), seconds = 2, out = File("tmp"))))

  test("the viewer with and without a scene"):
    assert(parse(Seq("--gui")) == Right(Options(gui = true)))
    assert(parse(Seq("--gui", "Cannon")) == Right(Options(scene = Some("Cannon"), gui = true)))

  test("the solver: classic unless --solver soft; --compare runs both, headless only"):
    assert(parse(Seq("Pyramid", "--solver", "soft")) == Right(Options(scene = Some("Pyramid"), solver = Some(SolverChoice.Soft))))
    assert(parse(Seq("--solver", "classic")) == Right(Options(solver = Some(SolverChoice.Classic))))
    assert(parse(Seq("--gui", "--solver", "Soft")) == Right(Options(gui = true, solver = Some(SolverChoice.Soft))))
    assert(parse(Seq("Pyramid", "--compare", "--seconds", "10", "--out", "docs/images")) ==
      Right(Options(scene = Some("Pyramid"), seconds = 10, out = File("docs/images"), compare = true)))
    assert(parse(Seq("--solver", "fast")).isLeft)
    assert(parse(Seq("--solver")).isLeft)
    assert(parse(Seq("--compare", "--solver", "soft")).isLeft)
    assert(parse(Seq("--solver", "soft", "--compare")).isLeft)
    assert(parse(Seq("--compare", "--gui")).isLeft)

  test("the solver a scene runs with: classic unless asked, the soft step for a soft-step-only scene, which refuses the classic step"):
    import sims.scenes.{Car, Pyramid}
    def solver(arguments: String*) = Main.solverFor(Scenes.find(arguments.head).get, parse(arguments).toOption.get)
    assert(solver("Pyramid") == Right(SolverChoice.Classic))
    assert(solver("Pyramid", "--solver", "soft") == Right(SolverChoice.Soft))
    assert(solver("Pyramid", "--compare") == Right(SolverChoice.Classic)) // the comparison runs both
    for scene <- Scenes.all.filter(_.softStepOnly) do
      assert(solver(scene.name) == Right(SolverChoice.Soft), scene.name)
      assert(solver(scene.name, "--gui") == Right(SolverChoice.Soft), scene.name)
      assert(solver(scene.name, "--solver", "soft") == Right(SolverChoice.Soft), scene.name)
    assert(solver("Car", "--solver", "classic") ==
      Left("Car runs under the soft step only (ClassicStep cannot step its joints): leave out --solver or say --solver soft"))
    assert(solver("Bridge", "--compare") ==
      Left("Bridge runs under the soft step only: --compare needs a scene that runs under both solvers"))
    assert(Main.listing.linesIterator.filter(_.endsWith("(soft step only)")).map(_.trim.takeWhile(_ != ' ')).toSeq ==
      Seq(Car.name, "Bridge", "Windmill"))
    assert(!Main.listing.linesIterator.exists(l => l.contains(Pyramid.name) && l.contains("soft step only")))
    assert(Main.Usage.contains("runs under the soft step only (Car, Bridge, Windmill) gets the soft step"))

  test("bad arguments are reported"):
    assert(parse(Seq("--seconds", "soon")).isLeft)
    assert(parse(Seq("--seconds", "-1")).isLeft)
    assert(parse(Seq("--out")).isLeft)
    assert(parse(Seq("--fast")).isLeft)
    assert(parse(Seq("Chain", "Cup")).isLeft)

  test("the listing names every scene"):
    for s <- Scenes.all do assert(Main.listing.contains(s.name))
