package sims.sweep.examples

import sims.dynamics.World
import sims.geometry.Vector2D
import sims.scenes.{Cannon, Scene}
import sims.solver.SoftStep
import sims.sweep.{Axis, Grid, Metric, Row, Stop, Sweep}

/** The Cannon scene's cannon, fired at a pyramid of 36 boxes, over the ball's muzzle speed and
  * the restitution and the friction of every shape: 20 x 10 x 10 = 2,000 runs of 5 simulated
  * seconds each, measuring how many of the boxes fall.
  *
  * The scene's own target is a pyramid of circles, which falls by itself: circles resting in
  * each other's hollows roll apart, friction or not (22 to 28 of its 36 fall in 5 s with no shot
  * fired), so counting them would measure the pyramid, not the shot. Boxes stand until hit, under
  * the soft step (`SoftStep`), which each run uses; under the classic step an eight-row pyramid
  * of boxes sags and falls by itself too (7 to 27 of its 36 boxes in 5 s, by the materials).
  */
object CannonSweep:
  /** Simulated time of a run: 5 s at 60 steps per second. */
  val Steps: Int = 300

  /** Muzzle speeds 5 to 24 m/s, in the scene's firing direction. */
  val Speeds: Axis = Axis.stepped("speed", 5, 24, 1)
  /** Restitution of every shape, 0 to 0.9 (a pair of shapes bounces with the product). */
  val Restitutions: Axis = Axis.evenly("restitution", 0, 0.9, 10)
  /** Friction of every shape, 0 to 0.9 (a pair of shapes rubs with the product). */
  val Frictions: Axis = Axis.evenly("friction", 0, 0.9, 10)

  /** Every combination of the three. */
  val parameters: Grid = Grid(Speeds, Restitutions, Frictions)

  /** Rows of the pyramid: 8 boxes at the bottom, 1 at the top, 36 in all. */
  val Rows: Int = 8
  /** Half the side of a box, m. */
  val HalfSide: Double = 0.25
  /** Distance of neighbouring boxes' centres in a row, m. */
  val Pitch: Double = 0.5625
  /** Centre of the pyramid's bottom row, m: where the scene's own pyramid stands. */
  val PyramidX: Double = 3

  // Bodies 0 and 1 are the ground and the backstop, then come the boxes, then the ball.
  private val FirstBox = 2
  private val Boxes = Rows * (Rows + 1) / 2

  /** Each box's place before the shot: row by row from the bottom, left to right. */
  val boxCentres: IndexedSeq[Vector2D] =
    for row <- 0 until Rows; i <- 0 until Rows - row
    yield Vector2D(PyramidX + (i - (Rows - row - 1) / 2.0) * Pitch, HalfSide + 2 * HalfSide * row)

  /** The scene of one run: Cannon's ground, backstop and cannon ball (at the row's speed, in
    * the scene's direction), the pyramid of boxes, and every shape's material set to the row's
    * restitution and friction, stepped by the soft step.
    */
  def build(row: Row): World =
    val world = Scene.worldOf(Scene.ground(21, centreX = 9), Scene.fixedBox(Vector2D(29.5, 1), 0.5, 1))
    world.solver = SoftStep()
    for centre <- boxCentres do world += Scene.box(centre, HalfSide, HalfSide)
    Cannon.fire(world)
    world.bodies.last.linearVelocity = Cannon.MuzzleVelocity.unit * row("speed")
    for shape <- world.shapes do
      shape.restitution = row("restitution")
      shape.friction = row("friction")
    world

  /** Boxes that ended at least half their side lower than they started: come down from their
    * row (the bottom row's boxes cannot, so at most 28 of the 36 do).
    */
  val fallen: Metric = Metric("fallen",
    world =>
      (0 until Boxes).count(i => world.bodies(FirstBox + i).pos.y < boxCentres(i).y - HalfSide).toDouble)

  /** How far the ball got: its centre's final x, m (the pyramid stands from 0.75 to 5.25). */
  val ballX: Metric = Metric("ballX", world => world.bodies.last.pos.x)

  /** The sweep: `parameters` (or fewer runs: another grid of the same axes' names). */
  def sweep(parameters: Grid = parameters): Sweep = Sweep(parameters, build, Stop.after(Steps), Seq(fallen, ballX))
