package sims.scenes

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.{Body, Rectangle, World}
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** `rain`, Box2D v3's benchmark scene of that name: it rains ragdolls ([[Human]]) onto `rows`
  * floors of 0.5 m boxes, 45 m apart (one fixed body of `rows` x 501 boxes). Every 8 steps a
  * new column of groups appears, a group of `groupSize` humans 0.5 m apart on each floor,
  * 40 m above it, until there are `columns`; from then on the oldest column is taken away and
  * dropped again, so the world keeps `rows` x `columns` x `groupSize` humans (11,000 bones in
  * the benchmark) and a steady stream of bodies joining and leaving. Soft step only (the
  * humans' joints have motors and springs).
  */
final case class Rain(rows: Int = Rain.BenchmarkRows, columns: Int = Rain.BenchmarkColumns,
    groupSize: Int = Rain.BenchmarkGroupSize) extends Scene:
  import Rain.*
  require(rows > 0 && columns > 0 && groupSize > 0,
    s"rows, columns and groupSize must be positive, got $rows, $columns, $groupSize")

  def name: String =
    if rows == BenchmarkRows && columns == BenchmarkColumns && groupSize == BenchmarkGroupSize then "rain"
    else s"rain-${rows}x${columns}x$groupSize"
  def description: String = s"Ragdolls rain onto $rows floors, $columns columns of $groupSize, the oldest dropped again."
  def view: Region = Region(-Span / 2, -1, Span / 2, FloorDistance * (rows - 1) + DropHeight + 2)
  override def softStepOnly: Boolean = true

  /** A rain world: its `postStep` drops a column every `Delay` steps. */
  final class RainWorld extends World:
    /** The humans of each column, per floor: `groups(column)(row)`, empty until dropped. */
    val groups: IndexedSeq[Array[Seq[Human]]] = IndexedSeq.fill(columns)(Array.fill(rows)(Seq.empty[Human]))
    /** Columns dropped so far (at most `columns`). */
    var columnCount: Int = 0
    private var nextColumn = 0
    private var steps = 0

    /** Drops a new column every `Delay` steps, or, once all are there, the oldest again. */
    override def postStep(): Unit =
      if steps % Delay == 0 then
        val column = if columnCount < columns then columnCount else nextColumn
        for row <- 0 until rows do
          groups(column)(row).foreach(_.removeFrom(this))
          groups(column)(row) = drop(this, row, column)
        if columnCount < columns then columnCount += 1 else nextColumn = (nextColumn + 1) % columns
      steps += 1

  /** The humans of one group, added to the world. */
  private def drop(world: World, row: Int, column: Int): Seq[Human] =
    val spacing = Span / columns
    val start = Vector2D(-Span / 2 + spacing * (column + 0.5), DropHeight + FloorDistance * row)
    for i <- 0 until groupSize yield
      val human = Human(start + Vector2D(HumanSpacing * i, 0), group = i + 1)
      human.addTo(world)
      human

  /** The floors: one fixed body of `rows` x 501 boxes. */
  def floors: Body =
    val boxes = ArrayBuffer.empty[Rectangle]
    for row <- 0 until rows; j <- 0 to GridCount do
      val box = Rectangle(GridSize / 2, GridSize / 2)
      box.pos = Vector2D(-Span / 2 + j * GridSize, row * FloorDistance)
      boxes += box
    val body = Body(boxes.toSeq*)
    body.fixed = true
    body

  def build(): Staged =
    val world = RainWorld()
    world.solver = SoftStep()
    world += floors
    Staged(world)

/** The benchmark's sizes and the scene's constants (Box2D's). */
object Rain:
  val BenchmarkRows: Int = 5
  val BenchmarkColumns: Int = 40
  val BenchmarkGroupSize: Int = 5
  /** The floors' boxes: side and number along a floor (plus one). */
  val GridSize: Double = 0.5
  val GridCount: Int = 500
  /** A floor's length, m. */
  val Span: Double = GridCount * GridSize
  /** Height between floors, and of a dropped group above its floor, m. */
  val FloorDistance: Double = 45
  val DropHeight: Double = 40
  /** Distance between the humans of a group, m. */
  val HumanSpacing: Double = 0.5
  /** Steps between two drops. */
  val Delay: Int = 8
