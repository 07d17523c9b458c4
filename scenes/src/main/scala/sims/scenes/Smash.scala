package sims.scenes

import sims.geometry.Vector2D

/** `smash`, Box2D v3's benchmark scene of that name, without gravity: a box of 8 m (density 8)
  * at (-20, 0) flying at 40 m/s into a wall of `columns` x `rows` boxes of 0.4 m (120 x 80,
  * 9,600 boxes, in the benchmark), side by side without gaps from x = 30. Box2D's wall starts
  * asleep (it costs nothing until hit); here every body starts awake.
  */
final case class Smash(columns: Int = Smash.BenchmarkColumns, rows: Int = Smash.BenchmarkRows) extends LayoutScene:
  import Smash.*
  require(columns > 0 && rows > 0, s"columns and rows must be positive, got $columns x $rows")

  def name: String = if columns == BenchmarkColumns && rows == BenchmarkRows then "smash" else s"smash-${columns}x$rows"
  def description: String = s"A heavy box at 40 m/s smashing into a wall of ${columns * rows} small boxes."
  def view: Region = Region(-30, -rows * Side, 30 + columns * Side + 20, rows * Side)

  lazy val layout: Layout =
    val ram = SceneBody(Outline.Box(RamHalfSide, RamHalfSide), Vector2D(-20, 0), fixed = false, RamDensity,
      Layout.StandardFriction, 0, velocity = Vector2D(RamSpeed, 0))
    val wall =
      for i <- 0 until columns; j <- 0 until rows yield SceneBody.square(Vector2D(i * Side + 30, (j - rows / 2.0) * Side), Side / 2)
    Layout(ram +: wall, IndexedSeq.empty, Vector2D.Null, Layout.StandardTimeStep, Region(-1e4, -1e4, 1e4, 1e4))

object Smash:
  /** The benchmark's wall. */
  val BenchmarkColumns: Int = 120
  val BenchmarkRows: Int = 80
  /** A wall box's side, m. */
  val Side: Double = 0.4
  /** The ram: half its side, m, its density, kg/m^2, and its speed, m/s. */
  val RamHalfSide: Double = 4.0
  val RamDensity: Double = 8.0
  val RamSpeed: Double = 40.0
