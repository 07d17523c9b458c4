package sims.playground

import java.io.File
import java.nio.{ByteBuffer, ByteOrder}
import org.scalatest.funsuite.AnyFunSuite
import sims.scenes.{BenchScenes, LayoutScene}
import sims.solver.{ClassicStep, SoftStep}

/** SiMS linked to WebAssembly by Scala.js's WebAssembly backend (the bench page's `benchPageWasm`)
  * and to JavaScript (`benchPage`), in headless Chromium (`bits.html` of `benchPage/bundles`): both
  * load, and both compute the JVM's bits.
  */
class WasmBrowserSpec extends AnyFunSuite with ChromiumPage:
  protected def folder: File = File(System.getProperty("sims.bench.bundles"))
  protected def page: String = "bits.html"
  protected def ready: String = "window.simsBundles !== undefined"

  /** A bench scene's state after `steps` steps in `bundle` ("javascript" or "wasm"): x, y and
    * angle of every body, as the bytes of little-endian doubles in hexadecimal (the sign of a zero included).
    */
  private def pageState(bundle: String, scene: String, solver: String, steps: Int): String =
    script(
      """const [bundle, scene, solver, steps] = arguments;
        |const world = window.simsBundles[bundle].world(scene, solver);
        |for (let i = 0; i < steps; i++) world.step();
        |const bytes = new Uint8Array(new Float64Array(world.state()).buffer);
        |return Array.from(bytes, (b) => b.toString(16).padStart(2, "0")).join("");""".stripMargin,
      bundle, scene, solver, Integer.valueOf(steps)).toString

  /** The same on the JVM, built as the bench page builds it. */
  private def jvmState(scene: String, solver: String, steps: Int): String =
    val world = BenchScenes.find(scene) match
      case Some(layout: LayoutScene) => layout.layout.world()
      case _ => fail(s"no layout scene $scene")
    world.solver = if solver == "SoftStep" then SoftStep() else ClassicStep
    world.enableSleep = false
    for _ <- 1 to steps do world.step()
    val buffer = ByteBuffer.allocate(24 * world.bodies.length).order(ByteOrder.LITTLE_ENDIAN)
    for body <- world.bodies do buffer.putDouble(body.pos.x).putDouble(body.pos.y).putDouble(body.rotation)
    buffer.array.map(b => f"${b & 0xff}%02x").mkString

  test("both bundles load with no console errors; the WebAssembly one is a module with its binary"):
    assertNoConsoleErrors()
    assert(script("return typeof window.simsBundles.wasm.world") == "function")
    assert(File(System.getProperty("sims.bench.bundles"), "wasm/main.wasm").length > 0)

  for (scene, solver) <- Seq(("pyramid-20", "SoftStep"), ("chain-100", "SoftStep"), ("ballpit-500", "SoftStep"),
      ("ballpit-500", "ClassicStep"))
  do
    test(s"$scene under $solver after 300 steps: the same bits in WebAssembly, in JavaScript and on the JVM"):
      val jvm = jvmState(scene, solver, 300)
      assert(pageState("wasm", scene, solver, 300) == jvm)
      assert(pageState("javascript", scene, solver, 300) == jvm)
      assertNoConsoleErrors()
