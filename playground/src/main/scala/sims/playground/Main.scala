package sims.playground

import org.scalajs.dom
import scala.scalajs.js
import sims.scenes.{Scenes, StateFingerprint}

/** Starts the playground on its page (index.html): wires the controls to a [[Playground]] and
  * offers `window.simsPlayground` for scripts and the browser tests: `state()`, `canvasPoint`,
  * `step(n)`, `load`, `fingerprint()` and `run(scene, solver, steps)` (a fresh world's
  * fingerprint after that many steps, away from the page's own).
  */
object Main:
  def main(args: Array[String]): Unit =
    val document = dom.document
    val canvas = document.getElementById("canvas").asInstanceOf[dom.HTMLCanvasElement]
    val playground = Playground(canvas, document.getElementById("info"))
    val sceneChooser = document.getElementById("scene").asInstanceOf[dom.HTMLSelectElement]
    val solverChooser = document.getElementById("solver").asInstanceOf[dom.HTMLSelectElement]
    val playButton = document.getElementById("play").asInstanceOf[dom.HTMLButtonElement]
    val actionButton = document.getElementById("action").asInstanceOf[dom.HTMLButtonElement]

    for scene <- Scenes.all do
      val option = document.createElement("option").asInstanceOf[dom.HTMLOptionElement]
      option.value = scene.name
      option.text = scene.name
      sceneChooser.appendChild(option)
    for name <- Playground.SolverNames do
      val option = document.createElement("option").asInstanceOf[dom.HTMLOptionElement]
      option.value = name
      option.text = name
      solverChooser.appendChild(option)
    sceneChooser.value = playground.sceneName

    // The solver in use, and only the solvers the scene may have enabled (the soft step alone
    // for a scene that runs under it only).
    def showSolver(): Unit =
      val offered = playground.solversOffered
      for i <- 0 until solverChooser.options.length do
        val option = solverChooser.options(i)
        option.disabled = !offered.contains(option.value)
      solverChooser.value = playground.solverInUse
      solverChooser.title =
        if offered.size == 1 then s"${playground.sceneName} runs under the soft step only" else ""
    showSolver()

    def showPlaying(): Unit = playButton.textContent = if playground.isPlaying then "Pause" else "Play"
    def showAction(): Unit =
      actionButton.textContent = playground.actionLabel.getOrElse("No action")
      actionButton.disabled = playground.actionLabel.isEmpty
    showPlaying()
    showAction()

    sceneChooser.addEventListener("change", (_: dom.Event) => { playground.load(sceneChooser.value); showAction(); showSolver() })
    solverChooser.addEventListener("change", (_: dom.Event) => playground.chooseSolver(solverChooser.value))
    playButton.addEventListener("click", (_: dom.Event) => { playground.setPlaying(!playground.isPlaying); showPlaying() })
    document.getElementById("step").addEventListener("click", (_: dom.Event) => { playground.step(); playground.draw() })
    document.getElementById("reset").addEventListener("click", (_: dom.Event) => { playground.reset(); showAction() })
    actionButton.addEventListener("click", (_: dom.Event) => playground.act())

    def canvasXY(event: dom.MouseEvent): (Double, Double) =
      val box = canvas.getBoundingClientRect()
      ((event.clientX - box.left) * canvas.width / box.width, (event.clientY - box.top) * canvas.height / box.height)
    canvas.addEventListener("mousedown",
      (event: dom.MouseEvent) => {
        val (x, y) = canvasXY(event)
        playground.pointerDown(x, y)
        event.preventDefault()
      })
    dom.window.addEventListener("mousemove",
      (event: dom.MouseEvent) => {
        val (x, y) = canvasXY(event)
        playground.pointerMove(x, y)
      })
    dom.window.addEventListener("mouseup", (_: dom.MouseEvent) => playground.release())
    canvas.addEventListener("wheel",
      (event: dom.WheelEvent) => {
        val (x, y) = canvasXY(event)
        playground.zoom(event.deltaY, x, y)
        event.preventDefault()
      })

    def animate(now: Double): Unit =
      playground.frame(now)
      dom.window.requestAnimationFrame(t => animate(t))
    dom.window.requestAnimationFrame(t => animate(t))

    val api = js.Dynamic.literal(
      state = () =>
        val world = playground.world
        js.Dynamic.literal(
          scene = playground.sceneName,
          linkedTo = Playground.LinkedTo,
          playing = playground.isPlaying,
          time = world.time,
          fingerprint = StateFingerprint(world),
          bodies = js.Array(world.bodies.toSeq.map(b => js.Array[Any](b.pos.x, b.pos.y, b.rotation, b.fixed))*))
      ,
      canvasPoint = (x: Double, y: Double) =>
        val (px, py) = playground.toCanvas(x, y)
        js.Array(px, py)
      ,
      step = (n: Int) =>
        for _ <- 1 to n do playground.step()
        playground.draw()
      ,
      load = (name: String) => { sceneChooser.value = name; playground.load(name); showAction(); showSolver() },
      fingerprint = () => StateFingerprint(playground.world),
      run = (scene: String, solver: String, steps: Int) =>
        val world = Scenes.find(scene).getOrElse(throw IllegalArgumentException(s"no scene named $scene")).build().world
        world.solver = Playground.solver(solver)
        for _ <- 1 to steps do world.step()
        StateFingerprint(world)
    )
    js.Dynamic.global.globalThis.updateDynamic("simsPlayground")(api)
