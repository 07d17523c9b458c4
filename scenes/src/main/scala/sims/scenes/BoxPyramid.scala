package sims.scenes

import sims.geometry.Vector2D

/** `pyramid-R`, a benchmark scene (and, with 12 rows, a golden one): a fixed ground box and R
  * rows of 0.5 m boxes, row r holding R - r boxes 0.5625 m apart, each row resting on the
  * one below. Laid out as Box2D v3's reference program lays it out (`pyramid-R` in
  * `shared/peers/box2d-v3/scenes.c`).
  */
final case class BoxPyramid(rows: Int) extends LayoutScene:
  import BoxPyramid.*
  require(rows > 0, s"a pyramid needs rows, got $rows")

  def name: String = s"pyramid-$rows"
  def description: String = s"A pyramid of ${rows * (rows + 1) / 2} boxes in $rows rows on the ground."
  def view: Region =
    val halfWidth = math.max(rows * Pitch / 2 + 1, 3.0)
    Region(-halfWidth, -1, halfWidth, 2 * HalfSide * rows + 1)

  lazy val layout: Layout =
    val ground = SceneBody.box(Vector2D(0, -0.5), GroundHalfWidth, 0.5, fixed = true)
    val boxes =
      for row <- 0 until rows; i <- 0 until rows - row yield
        val firstX = -0.5 * (rows - row - 1) * Pitch
        SceneBody.box(Vector2D(firstX + i * Pitch, HalfSide + 2 * HalfSide * row), HalfSide, HalfSide)
    Layout(ground +: boxes, IndexedSeq.empty, Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-GroundHalfWidth, 0, GroundHalfWidth, 2 * HalfSide * rows + 1))

object BoxPyramid:
  /** Half the side of a box, m. */
  val HalfSide: Double = 0.25
  /** Distance of neighbouring boxes' centres in a row, m. */
  val Pitch: Double = 0.5625
  /** Half the width of the ground box, m. */
  val GroundHalfWidth: Double = 40.0
