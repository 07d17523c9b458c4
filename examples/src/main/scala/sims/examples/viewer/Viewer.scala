package sims.examples.viewer

import java.awt.{BorderLayout, Font}
import java.awt.event.ActionEvent
import javax.swing.{
  BorderFactory, BoxLayout, JButton, JCheckBox, JComboBox, JFrame, JPanel, JTextArea, SwingUtilities, Timer, WindowConstants
}
import sims.examples.SolverChoice
import sims.scenes.{Scene, Scenes}

/** The interactive viewer: a scene chooser, a solver chooser (switching applies to the running
  * world; disabled, showing the soft step, while a scene that runs under the soft step only is
  * shown), start / stop / step / reset, the scene's action, overlay toggles and an info panel
  * around a [[SimulationPanel]].
  */
final class ViewerControls(initialScene: Scene, initialSolver: SolverChoice = SolverChoice.Classic)
    extends JPanel(BorderLayout()):
  /** The drawing area. */
  val simulation: SimulationPanel = SimulationPanel(initialScene, initialSolver)
  private var running = false
  private val chooser = JComboBox[String](Scenes.all.map(_.name).toArray)
  private val solverChooser = JComboBox[String](SolverChoice.values.map(_.label))
  private val startStop = JButton("Start")
  private val stepButton = JButton("Step")
  private val resetButton = JButton("Reset")
  private val actionButton = JButton("Action")
  private val contacts = JCheckBox("Contacts")
  private val boxes = JCheckBox("AABBs")
  private val grid = JCheckBox("Grid")
  private val infoText = JTextArea(10, 22)
  /** Steps and repaints at the world's own rate while running; refreshes the info always. */
  private val timer = Timer(math.max(1, math.round(1000 * simulation.staged.world.timeStep).toInt), (_: ActionEvent) => tick())

  chooser.setSelectedItem(initialScene.name)
  chooser.addActionListener(_ => Scenes.find(chooser.getSelectedItem.toString).foreach(select))
  solverChooser.setSelectedItem(initialSolver.label)
  // Set while the chooser is made to show the solver in use (not a choice of the user's).
  private var showingSolver = false
  solverChooser.addActionListener { _ =>
    if !showingSolver then
      SolverChoice.values.find(_.label == solverChooser.getSelectedItem).foreach { choice =>
        simulation.solver = choice
        refreshInfo()
      }
  }
  startStop.addActionListener(_ => setRunning(!running))
  stepButton.addActionListener(_ => { setRunning(false); simulation.step(); refreshInfo() })
  resetButton.addActionListener(_ => { simulation.reset(); refreshInfo() })
  actionButton.addActionListener(_ => simulation.act())
  contacts.addActionListener(_ => { simulation.showContacts = contacts.isSelected; simulation.repaint() })
  boxes.addActionListener(_ => { simulation.showBoxes = boxes.isSelected; simulation.repaint() })
  grid.addActionListener(_ => { simulation.showGrid = grid.isSelected; simulation.repaint() })
  infoText.setEditable(false)
  infoText.setFont(Font(Font.MONOSPACED, Font.PLAIN, 12))

  private val toolbar = JPanel()
  Seq(chooser, solverChooser, startStop, stepButton, resetButton, actionButton, contacts, boxes, grid).foreach(toolbar.add(_))
  private val side = JPanel()
  side.setLayout(BoxLayout(side, BoxLayout.Y_AXIS))
  side.setBorder(BorderFactory.createTitledBorder("Info"))
  side.add(infoText)
  add(toolbar, BorderLayout.NORTH)
  add(simulation, BorderLayout.CENTER)
  add(side, BorderLayout.EAST)
  updateActionButton()
  showSolver()
  refreshInfo()

  /** Whether the simulation is advancing. */
  def isRunning: Boolean = running

  /** Starts or stops the simulation. */
  def setRunning(value: Boolean): Unit =
    running = value
    startStop.setText(if running then "Stop" else "Start")

  /** Starts the timer (call once the panel is shown). */
  def startTimer(): Unit = timer.start()

  /** Stops the timer. */
  def stopTimer(): Unit = timer.stop()

  /** The info panel's current text. */
  def infoShown: String = infoText.getText

  /** Chooses a solver as the solver chooser does (for the tests and for scripts): nothing while
    * the chooser is disabled.
    */
  def chooseSolver(choice: SolverChoice): Unit =
    if solverChooser.isEnabled then solverChooser.setSelectedItem(choice.label)

  /** Chooses a scene as the scene chooser does (for the tests and for scripts). */
  def chooseScene(scene: Scene): Unit = chooser.setSelectedItem(scene.name)

  /** Whether the solver chooser may be used (not while a soft-step-only scene is shown). */
  def solverChoosable: Boolean = solverChooser.isEnabled

  /** The solver the chooser shows. */
  def solverShown: String = solverChooser.getSelectedItem.toString

  private def select(scene: Scene): Unit =
    simulation.load(scene)
    updateActionButton()
    showSolver()
    refreshInfo()

  /** Shows the solver in use; offers the choice only for a scene that runs under either step. */
  private def showSolver(): Unit =
    showingSolver = true
    try solverChooser.setSelectedItem(simulation.solver.label)
    finally showingSolver = false
    val only = simulation.scene.softStepOnly
    solverChooser.setEnabled(!only)
    solverChooser.setToolTipText(if only then s"${simulation.scene.name} runs under the soft step only" else null)

  private def updateActionButton(): Unit =
    val action = simulation.staged.action
    actionButton.setEnabled(action.isDefined)
    actionButton.setText(action.map(_.label).getOrElse("Action"))

  private def tick(): Unit =
    if running then simulation.step()
    refreshInfo()

  private def refreshInfo(): Unit = infoText.setText(simulation.info)

/** Opens the viewer window. */
object Viewer:
  /** Shows the viewer on `scene`, stepped by `solver`, in a new window (needs a display). */
  def open(scene: Scene, solver: SolverChoice = SolverChoice.Classic): Unit =
    SwingUtilities.invokeLater { () =>
      val controls = ViewerControls(scene, solver)
      val frame = JFrame("SiMS examples")
      frame.setDefaultCloseOperation(WindowConstants.EXIT_ON_CLOSE)
      frame.setContentPane(controls)
      frame.pack()
      frame.setLocationRelativeTo(null)
      frame.setVisible(true)
      controls.startTimer()
    }
