package sims.scenes

import sims.geometry.Vector2D

/** `ballpit-N`, a benchmark scene: N balls of radius 0.1 on a grid of pitch 0.22 m, 45 to a
  * row, each shifted sideways by at most 5 mm, dropping into a fixed container 10 m wide
  * inside. Laid out as Box2D v3's reference program lays it out (`ballpit-N` in
  * `shared/peers/box2d-v3/scenes.c`), to the last bit.
  */
final case class Ballpit(balls: Int) extends LayoutScene:
  import Ballpit.*
  require(balls > 0, s"a ball pit needs balls, got $balls")

  /** Rows of the initial grid. */
  val rows: Int = (balls + PerRow - 1) / PerRow

  /** Height of the walls' top: the top of the grid's highest ball plus [[Ballpit.WallAboveGrid]], m. */
  val wallTop: Double = FirstRowY + (rows - 1) * Pitch + Radius + WallAboveGrid

  def name: String = s"ballpit-$balls"
  def description: String = s"$balls balls of radius $Radius in $rows rows dropping into a container 10 m wide."
  def view: Region = Region(-HalfInner - 1, -1.5, HalfInner + 1, wallTop + 0.5)

  lazy val layout: Layout =
    def wall(side: Double) = SceneBody.box(Vector2D(side * (HalfInner + WallHalfThickness), 0.5 * (wallTop + WallBottom)),
      WallHalfThickness, 0.5 * (wallTop - WallBottom), fixed = true)
    val floor = SceneBody.box(Vector2D(0, -0.5), HalfInner + 2 * WallHalfThickness, 0.5, fixed = true)
    val random = java.util.Random(SeedBase + balls)
    val firstX = -0.5 * (PerRow - 1) * Pitch
    val grid =
      for i <- 0 until balls yield
        val jitter = (random.nextDouble() * 2 - 1) * MaxJitter
        SceneBody.circle(Vector2D(firstX + (i % PerRow) * Pitch + jitter, FirstRowY + (i / PerRow) * Pitch), Radius)
    Layout(IndexedSeq(floor, wall(-1), wall(1)) ++ grid, IndexedSeq.empty, Layout.StandardGravity,
      Layout.StandardTimeStep, Region(-HalfInner, 0, HalfInner, wallTop))

object Ballpit:
  /** Ball radius, m. */
  val Radius: Double = 0.1
  /** Distance of neighbouring grid points, m. */
  val Pitch: Double = 0.22
  /** Balls per row: as many as fit between the walls with 2 cm to spare. */
  val PerRow: Int = 45
  /** Half the inner width of the container, m. */
  val HalfInner: Double = 5.0
  /** Height of the first row's centres: 2 cm above the floor, m. */
  val FirstRowY: Double = Radius + 0.02
  /** Half the thickness of a wall, m. */
  val WallHalfThickness: Double = 0.25
  /** Bottom of the walls (they reach through the floor), m. */
  val WallBottom: Double = -1.0
  /** How far the walls reach above the top of the grid's highest ball, m. */
  val WallAboveGrid: Double = 1.0
  /** Largest sideways shift of a ball from its grid point, m. */
  val MaxJitter: Double = 0.005
  /** `java.util.Random(SeedBase + N)` draws the shifts of ballpit-N. */
  val SeedBase: Long = 20261121L
