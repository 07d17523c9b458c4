package sims.sweep

import java.nio.file.Files
import org.scalatest.funsuite.AnyFunSuite
import sims.dynamics.{Circle, World}
import sims.geometry.Vector2D

class SweepSpec extends AnyFunSuite:
  /** A ball dropped from the row's height: a sweep whose every number can be checked by hand. */
  private def drop(row: Row): World =
    val world = World()
    val ball = Circle(0.1, 1).asBody
    ball.pos = Vector2D(0, row("start"))
    world += ball
    world

  private val height = Metric("height", _.bodies.head.pos.y)
  private val time = Metric("time", _.time)

  test("a run steps its world the given number of steps and measures it"):
    val sweep = Sweep(Grid(Axis("start", IndexedSeq(10, 20))), drop, Stop.after(60), Seq(height, time))
    val table = sweep.run(LocalBackend(1))
    assert(table.size == 2)
    assert(table.results.map(_.steps) == IndexedSeq(60, 60))
    // One second of free fall in the classic step's semi-implicit Euler: each step adds g h to
    // the speed, then moves by speed h; after n steps the drop is g h^2 n (n + 1) / 2.
    val h = 1.0 / 60
    val fallen = 9.81 * h * h * 60 * 61 / 2
    assert(math.abs(table("height")(0) - (10 - fallen)) < 1e-9)
    assert(math.abs(table("height")(1) - (20 - fallen)) < 1e-9)
    assert(table("time").forall(t => math.abs(t - 1.0) < 1e-12))

  test("a run with a stop condition stops at the first step after which it holds"):
    val sweep = Sweep(Grid(Axis("start", IndexedSeq(1, 5, 1000))), drop,
      Stop.when(600)(_.bodies.head.pos.y < 0), Seq(height))
    val table = sweep.run(LocalBackend(1))
    val steps = table.results.map(_.steps)
    // From 1 m and 5 m the ball passes 0 within 10 s; from 1000 m it does not.
    assert(steps(0) < steps(1) && steps(1) < 600 && steps(2) == 600)
    assert(table("height")(0) < 0 && table("height")(1) < 0 && table("height")(2) > 0)
    // One step earlier it was still above 0.
    val before = Sweep(Grid(Axis("start", IndexedSeq(5))), drop, Stop.after(steps(1) - 1), Seq(height)).run()
    assert(before("height").head >= 0)
    // A condition that holds at once: no step at all.
    assert(Sweep(Grid(Axis("start", IndexedSeq(5))), drop, Stop.when(10)(_ => true), Seq(height)).run()
      .results.head.steps == 0)

  test("the table's columns and CSV: run, seed, parameters, steps, metrics"):
    val sweep = Sweep(Grid(Axis("start", IndexedSeq(10, 20))), drop, Stop.after(0), Seq(height), seed = 5)
    val table = sweep.run()
    assert(table.columns.map(_.name) == IndexedSeq("run", "seed", "start", "steps", "height"))
    val seeds = sweep.rows.map(_.seed)
    assert(table.toCsv == s"run,seed,start,steps,height\n0,${seeds(0)},10.0,0,10.0\n1,${seeds(1)},20.0,0,20.0\n")
    val file = Files.createTempFile("sweep", ".csv")
    try
      table.writeCsv(file)
      assert(Files.readString(file) == table.toCsv)
    finally Files.delete(file)

  test("the local back end gives the same table on 1, 2 and 3 threads, bit for bit"):
    val sweep = Sweep(RandomSample(12, Interval("start", 0.5, 3)), drop, Stop.when(300)(_.bodies.head.pos.y < 0.2),
      Seq(height, time), seed = 3)
    val one = sweep.run(LocalBackend(1))
    assert(sweep.run(LocalBackend(2)) == one)
    assert(sweep.run(LocalBackend(3)).toCsv == one.toCsv)
    assert(one.results.map(_.steps).distinct.size > 1)

  test("a failing run fails the sweep, naming the first failing row whatever the threads"):
    val sweep = Sweep(Grid(Axis("start", IndexedSeq(1, 2, 3, 4, 5, 6))),
      row => if row("start") >= 3 then throw IllegalStateException(s"no world at ${row("start")}") else drop(row),
      Stop.after(1), Seq(height))
    for threads <- Seq(1, 2, 4) do
      val failure = intercept[RunFailedException](sweep.run(LocalBackend(threads)))
      assert(failure.row.index == 2)
      assert(failure.getMessage.contains("run 2"))
      assert(failure.getCause.getMessage == "no world at 3.0")

  test("bad sweeps are refused, naming what is wrong"):
    def message(body: => Any): String = intercept[IllegalArgumentException](body).getMessage
    assert(message(LocalBackend(0)).contains("threads must be at least 1, got 0"))
    assert(message(Stop.after(-1)).contains("maxSteps must be at least 0, got -1"))
    assert(message(Sweep(Grid(Axis("steps", IndexedSeq(1))), drop, Stop.after(1), Seq(height)))
        .contains("steps twice"))
    assert(message(Sweep(Grid(Axis("height", IndexedSeq(1))), drop, Stop.after(1), Seq(height)))
        .contains("height twice"))
    assert(message(Metric("", _ => 0)).contains("must not be empty"))
    val table = Sweep(Grid(Axis("start", IndexedSeq(1))), drop, Stop.after(0), Seq(height)).run()
    assert(message(table("mass")).contains("no parameter or metric named 'mass'"))
