package sims.collision.broadphase

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks

/** The grid's two forms, sparse (hashed cells) and dense (a box of cells), hold the same chains. */
class CellGridSpec extends AnyFunSuite with ScalaCheckPropertyChecks:
  /** Each cell's chain of shapes, most recent first, for the cells from (-2, -2) to (columns + 1, rows + 1). */
  private def chains(grid: CellGrid, columns: Int, rows: Int): Seq[Seq[Int]] =
    for
      cx <- -2 to columns + 1
      cy <- -2 to rows + 1
    yield Iterator.iterate(grid.firstEntry(cx, cy))(grid.nextEntry).takeWhile(_ >= 0).map(grid.shapeOf).toSeq

  test("the same insertions give the same chains in both forms, and none outside the box") {
    val insertion = for cx <- Gen.choose(0, 29); cy <- Gen.choose(0, 19) yield (cx, cy)
    forAll(Gen.listOfN(300, insertion), minSuccessful(30)) { cells =>
      val sparse = CellGrid()
      val dense = CellGrid()
      // Two steps, the second with other insertions: a reset empties both forms.
      for step <- 0 until 2 do
        sparse.reset(cells.length)
        dense.reset(cells.length, 30, 20)
        assert(!sparse.isDense && dense.isDense)
        for ((cx, cy), i) <- cells.zipWithIndex if i % 2 == step do
          val slot = dense.open(cx, cy)
          assert(dense.head(slot) == dense.firstEntry(cx, cy))
          dense.push(slot, i)
          sparse.insert(cx, cy, i)
        assert(chains(dense, 30, 20) == chains(sparse, 30, 20))
        assert(chains(dense, 30, 20).flatten.sorted == cells.indices.filter(_ % 2 == step))
    }
  }

  test("a box of many more cells than shapes is sparse; a grid may change form from one reset to the next") {
    val grid = CellGrid()
    grid.reset(10, 1000, 1000)
    assert(!grid.isDense)
    grid.insert(999, 999, 0)
    grid.reset(10, 30, 20)
    assert(grid.isDense)
    assert(grid.firstEntry(999, 999) == -1)
    grid.insert(29, 19, 1)
    grid.reset(10)
    assert(!grid.isDense)
    assert(grid.firstEntry(29, 19) == -1)
    grid.insert(29, 19, 2)
    assert(grid.shapeOf(grid.firstEntry(29, 19)) == 2)
  }
