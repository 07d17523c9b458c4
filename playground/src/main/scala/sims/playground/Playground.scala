package sims.playground

import org.scalajs.dom
import scala.scalajs.js
import sims.dynamics.Body
import sims.dynamics.joints.MouseJoint
import sims.scenes.{Scene, Scenes, Staged, StateFingerprint}
import sims.solver.{ClassicStep, SoftStep, Solver}

/** The playground page's state and behaviour: one running scene drawn on the canvas, the
  * scene and solver choosers (a scene that runs under the soft step only is offered that alone), play / pause / step / reset, dragging bodies with the mouse
  * (dragging empty space pans, the wheel zooms) and the info line.
  */
final class Playground(canvas: dom.HTMLCanvasElement, info: dom.Element):
  private val context = canvas.getContext("2d").asInstanceOf[dom.CanvasRenderingContext2D]
  private var scene: Scene = Scenes.find("Pyramid").get
  private var solverName = "SoftStep"
  private var staged: Staged = build()
  private var view = View.fit(scene.view, canvas.width, canvas.height)
  private var playing = false
  private var lastStepMillis = 0.0
  private var lastFrame = -1.0
  private var owed = 0.0 // simulated time behind the clock while playing, s
  private var dragJoint: Option[MouseJoint] = None
  private var panFrom: Option[(Double, Double)] = None

  /** The running world. */
  def world: sims.dynamics.World = staged.world

  /** The name of the scene running. */
  def sceneName: String = scene.name

  /** Whether the world advances with the clock. */
  def isPlaying: Boolean = playing

  /** The name of the solver stepping the world: the chosen one, or "SoftStep" for a scene that
    * runs under the soft step only.
    */
  def solverInUse: String = if scene.softStepOnly then "SoftStep" else solverName

  /** The solvers the running scene may be stepped by, by name: both, or the soft step alone. */
  def solversOffered: Seq[String] = if scene.softStepOnly then Seq("SoftStep") else Playground.SolverNames

  private def build(): Staged =
    val built = scene.build()
    built.world.solver = Playground.solver(solverInUse)
    built

  /** Loads a fresh build of the scene of this name, fitted to the canvas; paused. */
  def load(name: String): Unit =
    scene = Scenes.find(name).getOrElse(throw IllegalArgumentException(s"no scene named $name"))
    dragJoint = None
    staged = build()
    view = View.fit(scene.view, canvas.width, canvas.height)
    lastStepMillis = 0
    draw()

  /** Chooses the solver by name ("ClassicStep" or "SoftStep"); the running world switches at its
    * next step, unless its scene runs under the soft step only: it keeps the soft step, and the
    * choice holds for the scenes loaded after it.
    */
  def chooseSolver(name: String): Unit =
    val solver = Playground.solver(name)
    solverName = name
    if !scene.softStepOnly then world.solver = solver
    draw()

  /** Starts or stops the clock. */
  def setPlaying(on: Boolean): Unit =
    playing = on
    owed = 0
    lastFrame = -1

  /** Advances the world by one step, measuring it. */
  def step(): Unit =
    val start = js.Date.now()
    world.step()
    lastStepMillis = js.Date.now() - start

  /** Rebuilds the scene from scratch, keeping the view and the solver. */
  def reset(): Unit =
    dragJoint = None
    staged = build()
    lastStepMillis = 0
    draw()

  /** Runs the scene's action (a cannon shot, ...), if it has one. */
  def act(): Unit = staged.action.foreach(_.run())

  /** The scene's action's label, if it has one. */
  def actionLabel: Option[String] = staged.action.map(_.label)

  /** Called once per animation frame: steps as many times as the clock asks (at most four,
    * so a slow world slows down instead of freezing the page), then draws.
    */
  def frame(now: Double): Unit =
    if playing then
      if lastFrame >= 0 then owed = math.min(owed + (now - lastFrame) / 1000, 4 * world.timeStep)
      lastFrame = now
      while owed >= world.timeStep do
        step()
        owed -= world.timeStep
    draw()

  /** Draws the world and updates the info line. */
  def draw(): Unit =
    Painter.paint(context, world, view)
    val contacts = world.contacts.map(_.points.size).sum
    info.textContent = f"${scene.name} · $solverInUse · ${world.bodies.length} bodies · $contacts contacts · " +
      f"${lastStepMillis}%.2f ms/step (${Playground.LinkedTo}) · t = ${world.time}%.2f s · state ${StateFingerprint(world)}"

  /** The pointer went down at canvas pixel (x, y): grab the free body there, else start panning. */
  def pointerDown(x: Double, y: Double): Unit =
    release()
    val point = view.toWorld(x, y)
    world.shapesAt(point).reverseIterator.map(_.body).find(!_.fixed) match
      case Some(body) =>
        val joint = MouseJoint(body, point, Playground.DragForcePerKilogram * body.mass)
        world += joint
        dragJoint = Some(joint)
      case None => panFrom = Some((x, y))
    draw()

  /** The pointer moved to canvas pixel (x, y). */
  def pointerMove(x: Double, y: Double): Unit =
    dragJoint.foreach(_.target = view.toWorld(x, y))
    panFrom.foreach { (fromX, fromY) =>
      view = view.panned(x - fromX, y - fromY)
      panFrom = Some((x, y))
    }
    if dragJoint.isDefined || panFrom.isDefined then draw()

  /** The pointer went up: let go of the body, stop panning. */
  def release(): Unit =
    dragJoint.foreach(world -= _)
    dragJoint = None
    panFrom = None

  /** The wheel turned by `delta` over canvas pixel (x, y): zoom about that point. */
  def zoom(delta: Double, x: Double, y: Double): Unit =
    view = view.zoomed(math.pow(1.0015, -delta), x, y)
    draw()

  /** The canvas pixel of world point (x, y), for tests. */
  def toCanvas(x: Double, y: Double): (Double, Double) = (view.pixelX(x), view.pixelY(y))

  /** The free body nearest the top of the view, for tests. */
  def bodies: collection.IndexedSeq[Body] = world.bodies

object Playground:
  /** How hard the mouse pulls: this many newtons per kilogram of the body. */
  val DragForcePerKilogram: Double = 50 * 9.81

  /** What this bundle was linked to: "WebAssembly" or "JavaScript". */
  val LinkedTo: String = if scala.scalajs.LinkingInfo.isWebAssembly then "WebAssembly" else "JavaScript"

  /** The solvers offered, by name. */
  val SolverNames: Seq[String] = Seq("ClassicStep", "SoftStep")

  /** The solver of this name. */
  def solver(name: String): Solver = name match
    case "ClassicStep" => ClassicStep
    case "SoftStep" => SoftStep()
    case other => throw IllegalArgumentException(s"no solver named $other; the solvers are ${SolverNames.mkString(", ")}")
