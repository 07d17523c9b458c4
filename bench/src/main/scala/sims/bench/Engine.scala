package sims.bench

import sims.scenes.{LayoutScene, Rain, Scene}
import sims.solver.{ClassicStep, Solver, SoftStep}

/** One scene built in one engine: stepped by the benchmark, inspected by the sanity check. */
trait EngineScene:
  /** Advances the scene by one time step. */
  def step(): Unit

  /** x, y and rotation of every free body, in the order the scene lists them. */
  def dynamicStates: Array[Double]

  /** x and y velocity and angular velocity of every free body, in the order the scene lists them. */
  def dynamicVelocities: Array[Double]

  /** Current distance of the centres each distance joint connects, in order. */
  def jointLengths: Array[Double]

  /** Current gap between the two bodies' points of each revolute joint's pin, in order, m. */
  def pinGaps: Array[Double]

/** The engines compared: SiMS with each of its two solvers, and the peers. */
enum Engine(val label: String):
  /** SiMS with its default solver, `ClassicStep` (SiMS 1.2's step). */
  case Sims extends Engine("SiMS")
  /** SiMS with `SoftStep(workers = 1)`, the soft step with its defaults on one thread, as the
    * peers run.
    */
  case SimsSoft extends Engine("SiMS-soft")
  /** SiMS with `SoftStep()`, the soft step with its defaults: as many workers as processors. */
  case SimsSoftWorkers extends Engine("SiMS-soft-workers")
  /** jBox2D 2.2.1.1 (Java port of Box2D 2.2). */
  case JBox2D extends Engine("jBox2D")
  /** dyn4j 5.0.2. */
  case Dyn4j extends Engine("dyn4j")

  /** The solver of a SiMS engine (a fresh value each time), none for a peer. */
  def solver: Option[Solver] = this match
    case Sims => Some(ClassicStep)
    case SimsSoft => Some(SoftStep(workers = 1))
    case SimsSoftWorkers => Some(SoftStep())
    case _ => None

  /** Builds the scene in this engine: any scene in SiMS, a layout in the peers. */
  def build(scene: Scene): EngineScene = (solver, this, scene) match
    case (Some(sims), _, _) => SimsBuilder.build(scene, sims)
    case (_, JBox2D, laidOut: LayoutScene) => JBox2DBuilder.build(laidOut.layout)
    case (_, Dyn4j, laidOut: LayoutScene) => Dyn4jBuilder.build(laidOut.layout)
    case _ => throw IllegalArgumentException(s"${scene.name} is not a layout: $label cannot build it")

object Engine:
  /** The engine with this label or enum name, case-insensitive. */
  def named(name: String): Engine =
    values.find(e => e.label.equalsIgnoreCase(name) || e.toString.equalsIgnoreCase(name))
      .getOrElse(throw IllegalArgumentException(s"unknown engine $name"))

  /** SiMS's two solvers, on one thread. */
  val sims: Seq[Engine] = Seq(Sims, SimsSoft)

  /** The peers. */
  val peers: Seq[Engine] = Seq(JBox2D, Dyn4j)

  /** The engines that run a scene: all of them for a layout, SiMS alone (with both solvers)
    * for any other scene (e.g. the original's BallStack), with the soft step alone for a
    * `softStepOnly` scene (Rain's ragdolls have motors and springs); the soft step with all the
    * workers too for a big scene (`sharesOut`).
    */
  def forScene(scene: Scene): Seq[Engine] =
    val engines = scene match
      case _: LayoutScene => values.toSeq.filterNot(_ == SimsSoftWorkers)
      case soft if soft.softStepOnly => Seq(SimsSoft)
      case _ => sims
    if sharesOut(scene) then engines :+ SimsSoftWorkers else engines

  /** Whether a scene is big enough for the soft step's workers to share its steps (4,000 bodies
    * or more): the scenes the bench runs with all of them as well.
    */
  def sharesOut(scene: Scene): Boolean = scene match
    case laidOut: LayoutScene => laidOut.layout.bodies.length >= 4000
    case _: Rain => true
    case _ => false
