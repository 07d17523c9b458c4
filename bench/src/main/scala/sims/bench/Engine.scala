package sims.bench

/** One scene built in one engine: stepped by the benchmark, inspected by the sanity check. */
trait EngineScene:
  /** Advances the scene by one time step. */
  def step(): Unit

  /** x, y and rotation of every dynamic body, in the order the scene description lists them. */
  def dynamicStates: Array[Double]

  /** Current distance of the centres each joint connects, in order. */
  def jointLengths: Array[Double]

/** The engines compared. */
enum Engine(val label: String):
  case Sims extends Engine("SiMS")
  case JBox2D extends Engine("jBox2D")
  case Dyn4j extends Engine("dyn4j")

  /** Builds the named scene (see [[Scenes.names]]) in this engine. */
  def build(scene: String): EngineScene = this match
    case Sims => SimsScenes.build(scene)
    case JBox2D => JBox2DScenes.build(scene)
    case Dyn4j => Dyn4jScenes.build(scene)

object Engine:
  /** The engine with this label or enum name, case-insensitive. */
  def named(name: String): Engine =
    values.find(e => e.label.equalsIgnoreCase(name) || e.toString.equalsIgnoreCase(name))
      .getOrElse(throw IllegalArgumentException(s"unknown engine $name"))

  /** The engines that run a scene: the original's BallStack is SiMS only. */
  def forScene(scene: String): Seq[Engine] =
    if scene == "ballstack" then Seq(Sims) else values.toSeq
