package sims.sweep.examples

import java.awt.Color
import org.scalatest.funsuite.AnyFunSuite
import sims.sweep.{Axis, Grid, LocalBackend, Metric, Stop, Sweep}

class HeatmapsSpec extends AnyFunSuite:
  // A table whose value is x * y in each of two panels: no simulation needed (no steps).
  private val table = Sweep(Grid(Axis("p", IndexedSeq(1, 2)), Axis("x", IndexedSeq(0, 1, 2)), Axis("y", IndexedSeq(0, 1))),
    row => { val w = sims.dynamics.World(); w.gravity = sims.geometry.Vector2D(row("x") * row("y") * row("p"), 0); w },
    Stop.after(0), Seq(Metric("v", _.gravity.x))).run(LocalBackend(1))

  test("one panel per value, the largest value in the scale's top colour and 0 in its bottom one"):
    val image = Heatmaps.draw(table, "x", "y", "p", "v", "test")
    // Panel 2's cell x = 2, y = 1 (its top right) holds the largest value, 4; x = 0 holds 0.
    // Panels are 3 x 2 cells of 14 pixels, 56 pixels from the left, 22 apart, 54 from the top.
    val panelLeft = 56 + 3 * 14 + 22
    val top = Color(image.getRGB(panelLeft + 2 * 14 + 7, 54 + 7))
    val zero = Color(image.getRGB(panelLeft + 7, 54 + 7))
    assert(top == Color(250, 230, 60), top.toString)
    assert(zero == Color(40, 20, 90), zero.toString)
    // Panel 1's largest value is 2, half way: neither end of the scale.
    val half = Color(image.getRGB(56 + 2 * 14 + 7, 54 + 7))
    assert(half != top && half != zero)

  test("a table missing a combination is refused"):
    val partial = table.copy(results = table.results.take(11))
    val error = intercept[IllegalArgumentException](Heatmaps.draw(partial, "x", "y", "p", "v", "test"))
    assert(error.getMessage == "requirement failed: the table has no run with p = 2.0, x = 2.0, y = 1.0")
