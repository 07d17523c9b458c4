package sims.sweep

import org.scalatest.funsuite.AnyFunSuite
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks

class ParametersSpec extends AnyFunSuite with ScalaCheckPropertyChecks:
  test("a grid has every combination, the last axis changing fastest"):
    val grid = Grid(Axis("a", IndexedSeq(1, 2)), Axis("b", IndexedSeq(10, 20, 30)))
    assert(grid.size == 6)
    assert(grid.names == IndexedSeq("a", "b"))
    assert(grid.rows(0).map(_.values) == IndexedSeq(
      IndexedSeq(1.0, 10.0), IndexedSeq(1.0, 20.0), IndexedSeq(1.0, 30.0),
      IndexedSeq(2.0, 10.0), IndexedSeq(2.0, 20.0), IndexedSeq(2.0, 30.0)))
    assert(grid.rows(0).map(_.index) == (0 until 6))
    assert(grid.row(4, 0)("b") == 20.0)

  test("evenly spaced and stepped axes hit their ends exactly"):
    val tenths = Axis.evenly("x", 0, 0.9, 10).values
    assert(tenths.head == 0 && tenths.last == 0.9 && tenths.size == 10)
    assert(tenths.zipWithIndex.forall((v, i) => math.abs(v - i / 10.0) < 1e-15))
    assert(Axis.evenly("x", 3, 7, 1).values == IndexedSeq(3.0))
    assert(Axis.evenly("x", 3, 7, 2).values == IndexedSeq(3.0, 7.0))
    assert(Axis.stepped("speed", 5, 24, 1).values == (5 to 24).map(_.toDouble))
    assert(Axis.stepped("x", 0, 1, 0.1).values.size == 11)
    assert(Axis.stepped("x", 0, 1.05, 0.1).values.last == 1.0)

  test("rows' seeds depend on the sweep's seed and the index alone, and differ"):
    val grid = Grid(Axis.evenly("x", 0, 1, 50))
    val seeds = grid.rows(7).map(_.seed)
    assert(seeds.distinct.size == 50)
    assert(grid.row(31, 7).seed == seeds(31))
    assert(grid.rows(8).map(_.seed).intersect(seeds).isEmpty)

  test("a random sample draws each value within its interval, the same for the same seed"):
    forAll { (seed: Long) =>
      val sample = RandomSample(20, Interval("a", -1, 2), Interval("b", 5, 5.5))
      val rows = sample.rows(seed)
      assert(rows.forall(r => r("a") >= -1 && r("a") < 2 && r("b") >= 5 && r("b") < 5.5))
      assert(sample.rows(seed) == rows)
      // Run 13's values do not depend on how many runs come before or after it.
      assert(RandomSample(14, Interval("a", -1, 2), Interval("b", 5, 5.5)).row(13, seed) == rows(13))
    }

  test("a random sample spreads its values over the interval"):
    val values = RandomSample(10000, Interval("u", 0, 1)).rows(42).map(_("u"))
    val mean = values.sum / values.size
    assert(math.abs(mean - 0.5) < 0.01, s"mean $mean")
    // Ten bins of about a thousand each.
    val bins = values.groupBy(v => (v * 10).toInt).view.mapValues(_.size).toMap
    assert(bins.keySet == (0 until 10).toSet)
    assert(bins.values.forall(n => n > 900 && n < 1100), bins.toString)
    // Two parameters of one row are not the same draw.
    val two = RandomSample(1000, Interval("a", 0, 1), Interval("b", 0, 1)).rows(1)
    assert(two.count(r => r("a") == r("b")) == 0)

  test("bad parameters are refused, naming what is wrong"):
    def message(body: => Any): String = intercept[IllegalArgumentException](body).getMessage
    assert(message(Axis("speed", IndexedSeq.empty)).contains("'speed' needs at least one value"))
    assert(message(Axis("speed", IndexedSeq(1, Double.NaN))).contains("non-finite value NaN"))
    assert(message(Axis("a b", IndexedSeq(1))).contains("'a b'"))
    assert(message(Axis.evenly("x", 0, 1, 0)).contains("count of at least 1, got 0"))
    assert(message(Axis.stepped("x", 0, 1, 0)).contains("step above 0, got 0.0"))
    assert(message(Interval("x", 2, 1)).contains("max (1.0) at least min (2.0)"))
    assert(message(Grid(Axis("x", IndexedSeq(1)), Axis("x", IndexedSeq(2)))).contains("x more than once"))
    assert(message(RandomSample(-1, Interval("x", 0, 1))).contains("count must be at least 0, got -1"))
    assert(message(Grid(Axis("x", IndexedSeq(1))).row(1, 0)).contains("index is from 0 to 0, got 1"))
    assert(message(Grid(Axis("x", IndexedSeq(1))).row(0, 0)("y")).contains("no parameter named 'y'"))
