package sims.bench

import sims.scenes.{LayoutScene, Scene}

/** One scene built in one engine: stepped by the benchmark, inspected by the sanity check. */
trait EngineScene:
  /** Advances the scene by one time step. */
  def step(): Unit

  /** x, y and rotation of every free body, in the order the scene lists them. */
  def dynamicStates: Array[Double]

  /** Current distance of the centres each joint connects, in order. */
  def jointLengths: Array[Double]

/** The engines compared. */
enum Engine(val label: String):
  case Sims extends Engine("SiMS")
  case JBox2D extends Engine("jBox2D")
  case Dyn4j extends Engine("dyn4j")

  /** Builds the scene in this engine: any scene in SiMS, a layout in the peers. */
  def build(scene: Scene): EngineScene = (this, scene) match
    case (Sims, _) => SimsBuilder.build(scene)
    case (JBox2D, laidOut: LayoutScene) => JBox2DBuilder.build(laidOut.layout)
    case (Dyn4j, laidOut: LayoutScene) => Dyn4jBuilder.build(laidOut.layout)
    case _ => throw IllegalArgumentException(s"${scene.name} is not a layout: $label cannot build it")

object Engine:
  /** The engine with this label or enum name, case-insensitive. */
  def named(name: String): Engine =
    values.find(e => e.label.equalsIgnoreCase(name) || e.toString.equalsIgnoreCase(name))
      .getOrElse(throw IllegalArgumentException(s"unknown engine $name"))

  /** The engines that run a scene: all of them for a layout, SiMS alone for any other scene
    * (e.g. the original's BallStack).
    */
  def forScene(scene: Scene): Seq[Engine] = scene match
    case _: LayoutScene => values.toSeq
    case _ => Seq(Sims)
