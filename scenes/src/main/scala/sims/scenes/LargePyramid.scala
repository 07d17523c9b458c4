package sims.scenes

import sims.geometry.Vector2D

/** `large_pyramid`, Box2D v3's benchmark scene of that name: a fixed ground box (half extents
  * 100 x 1 at (0, -1)) and a pyramid of 1 m boxes, `base` in the bottom row (5,050 boxes for
  * the benchmark's 100), side by side without gaps, each row centred on the one below.
  */
final case class LargePyramid(base: Int = LargePyramid.BenchmarkBase) extends LayoutScene:
  import LargePyramid.*
  require(base > 0, s"a pyramid needs a base, got $base")

  def name: String = if base == BenchmarkBase then "large_pyramid" else s"large_pyramid-$base"
  def description: String = s"A pyramid of ${base * (base + 1) / 2} boxes of 1 m, $base in the bottom row."
  def view: Region = Region(-base * HalfSide - 1, -2, base * HalfSide + 1, 2 * HalfSide * base + 1)

  lazy val layout: Layout =
    val ground = SceneBody.box(Vector2D(0, -1), GroundHalfWidth, 1, fixed = true)
    val boxes =
      for row <- 0 until base; j <- row until base
      yield
        // Box2D's benchmark: x = (i + 1) a + 2 (j - i) a - a base, y = (2 i + 1) a, a the half side.
        SceneBody.square(Vector2D((row + 1) * HalfSide + 2 * (j - row) * HalfSide - HalfSide * base,
            (2 * row + 1) * HalfSide), HalfSide)
    Layout(ground +: boxes, IndexedSeq.empty, Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-GroundHalfWidth, 0, GroundHalfWidth, 2 * HalfSide * base + 1))

object LargePyramid:
  /** The benchmark's bottom row. */
  val BenchmarkBase: Int = 100
  /** Half the side of a box, m. */
  val HalfSide: Double = 0.5
  /** Half the width of the ground box, m. */
  val GroundHalfWidth: Double = 100.0
