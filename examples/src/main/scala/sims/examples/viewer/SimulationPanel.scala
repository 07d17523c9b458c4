package sims.examples.viewer

import java.awt.{Dimension, Graphics, Graphics2D}
import java.awt.event.{MouseAdapter, MouseEvent, MouseWheelEvent}
import javax.swing.JPanel
import sims.examples.SolverChoice
import sims.examples.render.{RenderOptions, Renderer, Viewport}
import sims.dynamics.joints.MouseJoint
import sims.scenes.{Scene, Staged}

/** The viewer's drawing area: owns the running scene, steps it on request with the chosen
  * solver and paints it with the shared [[sims.examples.render.Renderer]]. Dragging a free body
  * pulls it with a [[sims.dynamics.joints.MouseJoint]]; dragging empty space pans the view; the
  * mouse wheel zooms about the pointer. It needs no window, so tests paint it off-screen.
  */
final class SimulationPanel(initialScene: Scene, initialSolver: SolverChoice = SolverChoice.Classic) extends JPanel:
  private var _scene = initialScene
  private var _solver = initialSolver
  private var _staged: Staged = build(initialScene)
  private var _viewport: Viewport = Viewport.fit(initialScene.view, 800, 600)
  private var lastStepNanos = 0L
  // Until the user zooms or pans, the view keeps showing the scene's whole view at any panel size.
  private var viewMoved = false
  private var dragJoint: Option[MouseJoint] = None

  /** Draw contact points and normals. */
  var showContacts: Boolean = false
  /** Draw bounding boxes. */
  var showBoxes: Boolean = false
  /** Draw the broadphase grid. */
  var showGrid: Boolean = false

  setPreferredSize(Dimension(800, 600))
  installMouse()

  /** The scene shown. */
  def scene: Scene = _scene

  /** The running world and action of the scene. */
  def staged: Staged = _staged

  /** The solver stepping the world: the chosen one, or the soft step for a scene that runs under
    * it only.
    */
  def solver: SolverChoice = SolverChoice.forScene(_scene, _solver)

  /** The solver chosen, for every scene that runs under either step. */
  def chosenSolver: SolverChoice = _solver

  /** Chooses `choice`'s solver: the running world switches to it from its next step on (unless
    * the scene runs under the soft step only: it keeps the soft step), and scenes loaded or reset
    * later start with it too.
    */
  def solver_=(choice: SolverChoice): Unit =
    _solver = choice
    if !_scene.softStepOnly then _staged.world.solver = choice.solver
    repaint()

  /** A fresh build of `scene`, stepped by the chosen solver (the soft step if it needs it). */
  private def build(scene: Scene): Staged =
    val built = scene.build()
    built.world.solver = SolverChoice.forScene(scene, _solver).solver
    built

  /** The current view (sized to the panel when painted). */
  def viewport: Viewport = _viewport

  /** Replaces the scene with a fresh build of `newScene` and fits its view to the panel. */
  def load(newScene: Scene): Unit =
    dragJoint = None
    _scene = newScene
    _staged = build(newScene)
    lastStepNanos = 0
    viewMoved = false
    _viewport = Viewport.fit(newScene.view, math.max(1, getWidth), math.max(1, getHeight))
    repaint()

  /** Rebuilds the current scene from scratch, keeping the view. */
  def reset(): Unit =
    dragJoint = None
    _staged = build(_scene)
    lastStepNanos = 0
    repaint()

  /** Advances the world by one step and measures it. */
  def step(): Unit =
    val start = System.nanoTime()
    _staged.world.step()
    lastStepNanos = System.nanoTime() - start
    repaint()

  /** Runs the scene's action, if it has one. */
  def act(): Unit =
    _staged.action.foreach(_.run())
    repaint()

  /** The text of the info panel: solver, counts, time and the last step's duration. Collisions
    * are the pairs in contact after the solver's last step, contacts their points (the soft
    * step's count its speculative ones).
    */
  def info: String =
    val world = _staged.world
    val contacts = world.contacts
    s"""Scene:      ${_scene.name}
       |Solver:     ${solver.label}${if _scene.softStepOnly then " (this scene's only one)" else ""}
       |Bodies:     ${world.bodies.length}
       |Shapes:     ${world.shapes.length}
       |Joints:     ${world.joints.length}
       |Collisions: ${contacts.length}
       |Contacts:   ${contacts.map(_.points.size).sum}
       |Time:       ${"%.3f".format(world.time)} s
       |Step time:  ${"%.3f".format(lastStepNanos / 1e6)} ms
       |Zoom:       ${"%.1f".format(_viewport.scale)} px/m""".stripMargin

  /** Options for the renderer from the toggles. */
  def renderOptions: RenderOptions =
    RenderOptions(contacts = showContacts, boxes = showBoxes, grid = showGrid,
      caption = f"${_scene.name}  ${solver.label}  t = ${_staged.world.time}%.2f s")

  override def paintComponent(graphics: Graphics): Unit =
    super.paintComponent(graphics)
    val width = math.max(1, getWidth)
    val height = math.max(1, getHeight)
    if _viewport.width != width || _viewport.height != height then
      _viewport = if viewMoved then _viewport.resized(width, height) else Viewport.fit(_scene.view, width, height)
    Renderer.draw(graphics.asInstanceOf[Graphics2D], _staged.world, _viewport, renderOptions, _staged.overlay())

  /** Zooms by `factor` about pixel (x, y). */
  def zoom(factor: Double, x: Double, y: Double): Unit =
    _viewport = _viewport.zoomed(factor, x, y)
    viewMoved = true
    repaint()

  /** Moves the view by (dx, dy) pixels. */
  def pan(dx: Double, dy: Double): Unit =
    _viewport = _viewport.panned(dx, dy)
    viewMoved = true
    repaint()

  /** The body being dragged, if any. */
  def dragged: Option[sims.dynamics.Body] = dragJoint.map(_.node2)

  /** Starts dragging the free body under pixel (x, y), if there is one: a mouse joint pulls
    * the grabbed point towards the pointer with a force of at most [[SimulationPanel.DragForcePerKilogram]]
    * times the body's mass. Returns whether a body was grabbed.
    */
  def grab(x: Double, y: Double): Boolean =
    release()
    val point = _viewport.toWorld(x, y)
    val world = _staged.world
    // The last free body joined (drawn on top) among the shapes under the pointer.
    world.shapesAt(point).reverseIterator.map(_.body).find(!_.fixed) match
      case Some(body) =>
        val joint = MouseJoint(body, point, SimulationPanel.DragForcePerKilogram * body.mass)
        world += joint
        dragJoint = Some(joint)
        true
      case None => false

  /** Moves the dragged body's target to pixel (x, y). */
  def dragTo(x: Double, y: Double): Unit =
    dragJoint.foreach(_.target = _viewport.toWorld(x, y))
    repaint()

  /** Lets go of the dragged body. */
  def release(): Unit =
    dragJoint.foreach(_staged.world -= _)
    dragJoint = None
    repaint()

  private def installMouse(): Unit =
    val handler = new MouseAdapter:
      private var lastX, lastY = 0
      private var panning = false
      override def mousePressed(e: MouseEvent): Unit =
        lastX = e.getX; lastY = e.getY
        panning = !(javax.swing.SwingUtilities.isLeftMouseButton(e) && grab(e.getX, e.getY))
      override def mouseReleased(e: MouseEvent): Unit = release()
      override def mouseDragged(e: MouseEvent): Unit =
        if panning then pan(e.getX - lastX, e.getY - lastY)
        else dragTo(e.getX, e.getY)
        lastX = e.getX; lastY = e.getY
      override def mouseWheelMoved(e: MouseWheelEvent): Unit =
        zoom(math.pow(1.15, -e.getPreciseWheelRotation), e.getX, e.getY)
    addMouseListener(handler)
    addMouseMotionListener(handler)
    addMouseWheelListener(handler)

/** Settings of the viewer's drawing area. */
object SimulationPanel:
  /** Bound of the dragging force per kilogram of the dragged body, N/kg (50 g). */
  val DragForcePerKilogram: Double = 50 * 9.81
