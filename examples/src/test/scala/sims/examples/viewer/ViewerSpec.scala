package sims.examples.viewer

import java.awt.Color
import java.awt.image.BufferedImage
import org.scalatest.funsuite.AnyFunSuite
import sims.examples.SolverChoice
import sims.examples.render.Renderer
import sims.scenes.{BallStack, Cannon, Car, Scenes}
import sims.solver.{ClassicStep, SoftStep}

/** The viewer's panels work without a display: they paint off-screen and respond to controls. */
class ViewerSpec extends AnyFunSuite:
  test("the tests run headless"):
    assert(java.awt.GraphicsEnvironment.isHeadless)

  test("the simulation panel paints a frame off-screen"):
    val panel = SimulationPanel(BallStack)
    panel.setSize(400, 300)
    val image = BufferedImage(400, 300, BufferedImage.TYPE_INT_RGB)
    val g = image.createGraphics()
    panel.paint(g)
    g.dispose()
    assert(panel.viewport.width == 400 && panel.viewport.height == 300)
    // The upper corner is empty sky, the bottom middle is the ground.
    assert(Color(image.getRGB(5, 40)) == Renderer.Background)
    val ground = panel.viewport
    assert(Color(image.getRGB(ground.pixelX(0).toInt, ground.pixelY(-0.5).toInt)) == Renderer.FixedFill)

  test("the whole viewer, with controls and every overlay, paints off-screen"):
    val controls = ViewerControls(Cannon)
    controls.setSize(1000, 700)
    controls.doLayout()
    controls.simulation.showContacts = true
    controls.simulation.showBoxes = true
    controls.simulation.showGrid = true
    controls.simulation.setSize(700, 600)
    val image = BufferedImage(1000, 700, BufferedImage.TYPE_INT_RGB)
    val g = image.createGraphics()
    controls.paint(g)
    g.dispose()
    assert(controls.infoShown.contains("Bodies:"))

  test("step, action, reset and scene change"):
    val panel = SimulationPanel(Cannon)
    val bodies = panel.staged.world.bodies.size
    panel.step()
    assert(panel.staged.world.time > 0)
    assert(panel.info.contains(s"Bodies:     $bodies"))
    panel.act()
    assert(panel.staged.world.bodies.size == bodies + 1, "the cannon fired another ball")
    panel.reset()
    assert(panel.staged.world.time == 0 && panel.staged.world.bodies.size == bodies)
    panel.load(Scenes.all.last)
    assert(panel.scene == Scenes.all.last)

  test("the solver switch applies to the running world, and to worlds reset or loaded after it"):
    val controls = ViewerControls(sims.scenes.Stacking)
    val panel = controls.simulation
    val world = panel.staged.world
    assert(world.solver == ClassicStep && panel.solver == SolverChoice.Classic)
    for _ <- 1 to 10 do panel.step()
    controls.chooseSolver(SolverChoice.Soft)
    assert(panel.staged.world eq world, "the same world runs on")
    assert(world.solver.isInstanceOf[SoftStep] && panel.solver == SolverChoice.Soft)
    panel.step()
    assert(world.time > 10.5 * world.timeStep)
    assert(panel.info.contains("Solver:     soft step"))
    panel.reset()
    assert(panel.staged.world.solver.isInstanceOf[SoftStep])
    panel.load(BallStack)
    assert(panel.staged.world.solver.isInstanceOf[SoftStep])
    controls.chooseSolver(SolverChoice.Classic)
    assert(panel.staged.world.solver == ClassicStep)
    assert(ViewerControls(BallStack, SolverChoice.Soft).simulation.staged.world.solver.isInstanceOf[SoftStep])

  test(
    "a soft-step-only scene runs under the soft step: the solver chooser shows it, disabled, and the choice returns with the next scene"):
    val controls = ViewerControls(sims.scenes.Stacking)
    val panel = controls.simulation
    assert(controls.solverChoosable && controls.solverShown == SolverChoice.Classic.label)
    controls.chooseScene(Car)
    assert(panel.scene == Car && panel.staged.world.solver.isInstanceOf[SoftStep])
    assert(panel.solver == SolverChoice.Soft && panel.chosenSolver == SolverChoice.Classic)
    assert(!controls.solverChoosable && controls.solverShown == SolverChoice.Soft.label)
    assert(panel.info.contains("Solver:     soft step (this scene's only one)"))
    val world = panel.staged.world
    val solver = world.solver
    controls.chooseSolver(SolverChoice.Classic) // the chooser is disabled: nothing happens
    panel.solver = SolverChoice.Classic // remembered for the next scene; this one keeps its soft step
    assert((world.solver eq solver) && controls.solverShown == SolverChoice.Soft.label)
    for _ <- 1 to 10 do panel.step()
    panel.reset()
    assert(panel.staged.world.solver.isInstanceOf[SoftStep])
    controls.chooseScene(sims.scenes.Stacking)
    assert(panel.staged.world.solver == ClassicStep && controls.solverChoosable)
    assert(controls.solverShown == SolverChoice.Classic.label)
    val opened = ViewerControls(Car, SolverChoice.Classic)
    assert(opened.simulation.staged.world.solver.isInstanceOf[SoftStep] && !opened.solverChoosable)

  test("the info panel counts the solver's contacts"):
    for choice <- SolverChoice.values do
      val panel = SimulationPanel(sims.scenes.Stacking, choice)
      for _ <- 1 to 30 do panel.step()
      val points = panel.staged.world.contacts.map(_.points.size).sum
      assert(points > 0, choice.label)
      assert(panel.info.contains(s"Contacts:   $points"), choice.label)

  test("zoom and pan change the view"):
    val panel = SimulationPanel(BallStack)
    val scale = panel.viewport.scale
    panel.zoom(2, 10, 10)
    assert(panel.viewport.scale == 2 * scale)
    val centre = panel.viewport.centre
    panel.pan(50, 0)
    assert(panel.viewport.centre.x < centre.x)

  test("dragging a body with the mouse lifts it; empty space grabs nothing"):
    val panel = SimulationPanel(sims.scenes.Stacking)
    panel.setSize(600, 450)
    val image = BufferedImage(600, 450, BufferedImage.TYPE_INT_RGB)
    panel.paint(image.createGraphics()) // sizes the view to the panel
    val world = panel.staged.world
    val top = world.bodies.last
    val viewport = panel.viewport
    assert(!panel.grab(viewport.pixelX(2.5), viewport.pixelY(3.5)), "nothing there")
    assert(panel.grab(viewport.pixelX(top.pos.x), viewport.pixelY(top.pos.y)))
    assert(panel.dragged.contains(top))
    val start = top.pos
    panel.dragTo(viewport.pixelX(start.x), viewport.pixelY(start.y + 1))
    for _ <- 1 to 60 do panel.step()
    assert(top.pos.y > start.y + 0.7, s"the box was lifted from $start to ${top.pos}")
    val drawn = BufferedImage(600, 450, BufferedImage.TYPE_INT_RGB)
    panel.paint(drawn.createGraphics())
    panel.release()
    assert(panel.dragged.isEmpty && world.joints.isEmpty)
