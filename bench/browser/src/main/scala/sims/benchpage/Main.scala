package sims.benchpage

import scala.scalajs.js
import sims.scenes.{BenchScenes, Layout, LayoutScene, Outline}
import sims.solver.{ClassicStep, SoftStep}

/** The SiMS side of the browser benchmark page (bench/browser/site): offers
  * `window.simsBench` (this bundle, JavaScript) to the page's script, which times SiMS and the
  * JavaScript engines alike; `WasmMain` offers the same as `window.simsBenchWasm` from the bundle
  * linked to WebAssembly.
  * `layout(name)` gives a bench scene as plain values for the other engines to build (the same
  * `sims.scenes.Layout` the JVM bench's peers translate); `world(name, solver)` a SiMS world of it with
  * `step()`, `state()` (x, y, angle of every body) and `jointLengths()`.
  */
object Main:
  /** The bench scenes the page runs: the ball pits up to 4000 balls, the pyramid and the chain. */
  val Names: Seq[String] = Seq("ballpit-500", "ballpit-1000", "ballpit-2000", "ballpit-4000", "pyramid-20", "chain-100")

  private def layoutScene(name: String): LayoutScene = BenchScenes.find(name) match
    case Some(scene: LayoutScene) => scene
    case _ => throw IllegalArgumentException(s"no layout scene named $name")

  /** The layout as JavaScript values: bodies [kind (0 circle, 1 box), x, y, radius or half
    * width, half height, fixed, density, friction, restitution, no-collide group], joints [i, j].
    */
  private def exported(layout: Layout): js.Object = js.Dynamic.literal(
    bodies = js.Array(layout.bodies.map { b =>
      val (kind, a, c) = b.outline match
        case Outline.Circle(radius) => (0, radius, 0.0)
        case Outline.Box(halfWidth, halfHeight) => (1, halfWidth, halfHeight)
      js.Array[Any](kind, b.centre.x, b.centre.y, a, c, b.fixed, b.density, b.friction, b.restitution, b.noCollideGroup)
    }*),
    joints = js.Array(layout.joints.map(j => js.Array(j.body1, j.body2))*),
    gravity = js.Array(layout.gravity.x, layout.gravity.y),
    timeStep = layout.timeStep,
    bounds = js.Array(layout.bounds.minX, layout.bounds.minY, layout.bounds.maxX, layout.bounds.maxY))

  def main(args: Array[String]): Unit = offer("simsBench")

  /** Sets the page's global `name` to this bundle's bench interface. */
  def offer(name: String): Unit =
    val api = js.Dynamic.literal(
      names = js.Array(Names*),
      layout = (name: String) => exported(layoutScene(name).layout),
      world = (name: String, solver: String) =>
        val world = layoutScene(name).layout.world()
        world.solver = if solver == "SoftStep" then SoftStep() else ClassicStep
        // The page measures the step's work, as the JVM bench does: no body falls asleep (the peers' sleeping is off too).
        world.enableSleep = false
        val bodies = world.bodies.toIndexedSeq
        val joints = world.joints.toIndexedSeq.collect { case d: sims.dynamics.joints.DistanceJoint => d }
        js.Dynamic.literal(
          step = () => world.step(),
          state = () =>
            val out = new js.Array[Double](3 * bodies.length)
            var i = 0
            while i < bodies.length do
              out(3 * i) = bodies(i).pos.x
              out(3 * i + 1) = bodies(i).pos.y
              out(3 * i + 2) = bodies(i).rotation
              i += 1
            out
          ,
          jointLengths = () => js.Array(joints.map(j => (j.connection2 - j.connection1).length)*)
        )
    )
    js.Dynamic.global.globalThis.updateDynamic(name)(api)
