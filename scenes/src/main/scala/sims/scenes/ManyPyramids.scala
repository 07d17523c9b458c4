package sims.scenes

import sims.geometry.Vector2D

/** `many_pyramids`, Box2D v3's benchmark scene of that name: `rows` x `columns` small pyramids
  * of 1 m boxes (10 in the bottom row, 55 boxes each; 20 x 20 pyramids, 22,000 boxes, in the
  * benchmark), one row of pyramids on each of `rows` fixed floors 11 m apart. Box2D's floors are
  * segments 220 m long; here each is a fixed box 0.1 m thick whose top face is the segment.
  */
final case class ManyPyramids(rows: Int = ManyPyramids.BenchmarkRows, columns: Int = ManyPyramids.BenchmarkColumns)
    extends LayoutScene:
  import ManyPyramids.*
  require(rows > 0 && columns > 0, s"rows and columns must be positive, got $rows x $columns")

  def name: String =
    if rows == BenchmarkRows && columns == BenchmarkColumns then "many_pyramids" else s"many_pyramids-${rows}x$columns"
  def description: String = s"$rows x $columns pyramids of ${Boxes} boxes, on $rows floors."
  def view: Region = Region(-groundWidth / 2 - 1, -1, groundWidth / 2 + 1, rows * FloorPitch + 1)

  /** The floors' length, m. */
  def groundWidth: Double = 2 * HalfSide * columns * (Base + 1)

  lazy val layout: Layout =
    val floors = (0 until rows).map(i =>
      SceneBody.box(Vector2D(0, i * FloorPitch - FloorHalfThickness), groundWidth / 2, FloorHalfThickness, fixed = true))
    val baseWidth = 2 * HalfSide * Base
    val boxes =
      for
        floor <- 0 until rows
        column <- 0 until columns
        centreX = -0.5 * groundWidth + column * (baseWidth + 2 * HalfSide) + 2 * HalfSide
        row <- 0 until Base
        j <- row until Base
      yield SceneBody.square(Vector2D((row + 1) * HalfSide + 2 * (j - row) * HalfSide + centreX - 0.5,
          (2 * row + 1) * HalfSide + floor * FloorPitch), HalfSide)
    Layout(floors ++ boxes, IndexedSeq.empty, Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-groundWidth / 2, 0, groundWidth / 2, rows * FloorPitch))

object ManyPyramids:
  /** The benchmark's rows and columns of pyramids. */
  val BenchmarkRows: Int = 20
  val BenchmarkColumns: Int = 20
  /** Boxes in a pyramid's bottom row. */
  val Base: Int = 10
  /** Boxes in a pyramid. */
  val Boxes: Int = Base * (Base + 1) / 2
  /** Half the side of a box, m. */
  val HalfSide: Double = 0.5
  /** Height between floors, m: a pyramid's height plus one box. */
  val FloorPitch: Double = 2 * HalfSide * (Base + 1)
  /** Half the thickness of a floor box, m. */
  val FloorHalfThickness: Double = 0.05
