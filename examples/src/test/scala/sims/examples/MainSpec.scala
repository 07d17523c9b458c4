package sims.examples

import java.io.File
import org.scalatest.funsuite.AnyFunSuite

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
    assert(parse(Seq("Pyramid", "--solver", "soft")) == Right(Options(scene = Some("Pyramid"), solver = SolverChoice.Soft)))
    assert(parse(Seq("--solver", "classic")) == Right(Options()))
    assert(parse(Seq("--gui", "--solver", "Soft")) == Right(Options(gui = true, solver = SolverChoice.Soft)))
    assert(parse(Seq("Pyramid", "--compare", "--seconds", "10", "--out", "docs/images")) ==
      Right(Options(scene = Some("Pyramid"), seconds = 10, out = File("docs/images"), compare = true)))
    assert(parse(Seq("--solver", "fast")).isLeft)
    assert(parse(Seq("--solver")).isLeft)
    assert(parse(Seq("--compare", "--solver", "soft")).isLeft)
    assert(parse(Seq("--solver", "soft", "--compare")).isLeft)
    assert(parse(Seq("--compare", "--gui")).isLeft)

  test("bad arguments are reported"):
    assert(parse(Seq("--seconds", "soon")).isLeft)
    assert(parse(Seq("--seconds", "-1")).isLeft)
    assert(parse(Seq("--out")).isLeft)
    assert(parse(Seq("--fast")).isLeft)
    assert(parse(Seq("Chain", "Cup")).isLeft)

  test("the listing names every scene"):
    for s <- sims.scenes.Scenes.all do assert(Main.listing.contains(s.name))
