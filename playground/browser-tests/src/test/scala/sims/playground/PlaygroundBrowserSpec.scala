package sims.playground

import java.io.File
import java.nio.file.{Files, StandardCopyOption}
import java.time.Duration
import org.openqa.selenium.{By, OutputType}
import org.openqa.selenium.interactions.Actions
import org.openqa.selenium.support.ui.Select
import org.scalatest.funsuite.AnyFunSuite
import scala.jdk.CollectionConverters.*
import sims.scenes.{PlatformHashesSpec, Scenes, StateFingerprint}
import sims.solver.{ClassicStep, SoftStep}

/** The playground page (`playground/staticSite`) in headless Chromium, used as a person would:
  * the choosers, the buttons and the mouse; its state read through `window.simsPlayground`.
  */
class PlaygroundBrowserSpec extends AnyFunSuite with ChromiumPage:
  protected def folder: File = File(System.getProperty("sims.playground.site"))
  protected def page: String = "index.html"
  protected def ready: String = "window.simsPlayground !== undefined"

  private def number(value: AnyRef): Double = value.asInstanceOf[Number].doubleValue

  /** The bodies now: x, y, rotation, fixed. */
  private def bodies(): IndexedSeq[(Double, Double, Double, Boolean)] =
    script("return window.simsPlayground.state().bodies").asInstanceOf[java.util.List[java.util.List[AnyRef]]]
      .asScala.toIndexedSeq.map(b => (number(b.get(0)), number(b.get(1)), number(b.get(2)), b.get(3) == java.lang.Boolean.TRUE))

  private def element(id: String) = browser.driver.findElement(By.id(id))

  /** Chooses scene and solver with the page's choosers, paused, freshly built. */
  private def choose(scene: String, solver: String): Unit =
    if script("return window.simsPlayground.state().playing") == java.lang.Boolean.TRUE then element("play").click()
    Select(element("scene")).selectByValue(scene)
    Select(element("solver")).selectByValue(solver)
    element("reset").click()

  private def play(seconds: Double): Unit =
    element("play").click()
    Thread.sleep((seconds * 1000).toLong)
    element("play").click()

  test("the page loads with no console errors, shows every scene and both solvers"):
    assertNoConsoleErrors()
    val scenes = Select(element("scene")).getOptions.asScala.map(_.getAttribute("value")).toSeq
    assert(scenes == Scenes.all.map(_.name))
    assert(Select(element("solver")).getOptions.asScala.map(_.getAttribute("value")).toSeq == Seq("ClassicStep", "SoftStep"))

  test("a scene that runs under the soft step only: the solver chooser shows SoftStep with ClassicStep disabled, and it runs"):
    choose("Pyramid", "ClassicStep")
    Select(element("scene")).selectByValue("Car")
    val solver = Select(element("solver"))
    assert(solver.getFirstSelectedOption.getAttribute("value") == "SoftStep")
    assert(solver.getOptions.asScala.filterNot(_.isEnabled).map(_.getAttribute("value")).toSeq == Seq("ClassicStep"))
    script("window.simsPlayground.step(30)")
    val world = Scenes.find("Car").get.build().world
    world.solver = SoftStep()
    for _ <- 1 to 30 do world.step()
    assert(script("return window.simsPlayground.fingerprint()") == StateFingerprint(world))
    // The next scene runs under either step: the choice made before (ClassicStep) holds again.
    Select(element("scene")).selectByValue("Pyramid")
    assert(Select(element("solver")).getFirstSelectedOption.getAttribute("value") == "ClassicStep")
    assert(Select(element("solver")).getOptions.asScala.forall(_.isEnabled))
    assertNoConsoleErrors()

  test("the canvas is not blank: the scene's bodies cover a good part of it in several colours"):
    choose("Pyramid", "SoftStep")
    val counts = script("""
      const c = document.getElementById('canvas');
      const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      const colours = new Set(); let painted = 0;
      for (let i = 0; i < data.length; i += 4) {
        const rgb = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        if (rgb !== 0xf7f7f2) painted++;
        colours.add(rgb);
      }
      return [painted, colours.size, c.width * c.height];""").asInstanceOf[java.util.List[AnyRef]]
    val (painted, colours, total) = (number(counts.get(0)), number(counts.get(1)), number(counts.get(2)))
    assert(painted / total > 0.1, s"only $painted of $total pixels painted")
    assert(colours >= 6, s"$colours colours")
    val shot = browser.driver.getScreenshotAs(OutputType.FILE)
    Files.copy(shot.toPath, File(System.getProperty("sims.playground.screenshot")).toPath, StandardCopyOption.REPLACE_EXISTING)

  test("a body falls: Restitution's balls drop under gravity while the page plays"):
    choose("Restitution", "ClassicStep")
    val before = bodies()
    play(1.0)
    val after = bodies()
    val free = before.indices.filterNot(i => before(i)._4)
    assert(free.nonEmpty)
    val drops = free.map(i => before(i)._2 - after(i)._2)
    assert(drops.max > 0.5, s"drops ${drops.mkString(", ")} m")
    assert(number(script("return window.simsPlayground.state().time")) > 0.5)

  test("the pyramid under SoftStep stands after 5 s: every box within half a box of its start, none tipped"):
    choose("Pyramid", "SoftStep")
    val before = bodies()
    play(5.0)
    val after = bodies()
    val time = number(script("return window.simsPlayground.state().time"))
    assert(time > 2.0, s"only $time s simulated in 5 s")
    for i <- before.indices if !before(i)._4 do
      val moved = math.hypot(after(i)._1 - before(i)._1, after(i)._2 - before(i)._2)
      assert(moved < 0.5, s"box $i moved $moved m")
      val tilt = math.abs(after(i)._3 - math.round(after(i)._3 / (math.Pi / 2)) * (math.Pi / 2))
      assert(tilt < 0.2, s"box $i turned $tilt rad")

  test("a mouse drag moves a body: the pyramid's top box follows the pointer up"):
    choose("Pyramid", "SoftStep")
    val before = bodies()
    val top = before.indices.filterNot(i => before(i)._4).maxBy(i => before(i)._2)
    val point = script(s"return window.simsPlayground.canvasPoint(${before(top)._1}, ${before(top)._2})")
      .asInstanceOf[java.util.List[AnyRef]]
    val canvas = element("canvas")
    val (x, y) = (number(point.get(0)), number(point.get(1)))
    element("play").click()
    // Held while the state is read: once let go, the box may fall back (how far depends on
    // the frame rate of a loaded machine).
    Actions(browser.driver)
      .moveToElement(canvas, (x - canvas.getSize.width / 2.0).toInt, (y - canvas.getSize.height / 2.0).toInt)
      .clickAndHold()
      .moveByOffset(0, -40).pause(Duration.ofMillis(400))
      .moveByOffset(0, -40).pause(Duration.ofMillis(400))
      .moveByOffset(0, -40).pause(Duration.ofMillis(1200))
      .perform()
    val held = bodies()
    Actions(browser.driver).release().perform()
    element("play").click()
    val rise = held(top)._2 - before(top)._2
    assert(rise > 0.3, s"the top box rose $rise m")

  test("the page's state after 300 clicks on Step equals the JVM's, bit for bit"):
    choose("Chain", "ClassicStep")
    // The first click through the driver (the pointer's path), the other 299 from the page's own
    // script: the same click events, without a driver round trip for each.
    element("step").click()
    script("const step = document.getElementById('step'); for (let i = 1; i < 300; i++) step.click()")
    val info = element("info").getText
    val page = "state ([0-9a-f]{16})".r.findFirstMatchIn(info).map(_.group(1)).getOrElse(fail(s"no state in '$info'"))
    val world = Scenes.find("Chain").get.build().world
    world.solver = ClassicStep
    for _ <- 1 to 300 do world.step()
    assert(number(script("return window.simsPlayground.state().time")) == world.time)
    assert(page == StateFingerprint(world))

  /** Five scenes after 600 steps under each step in the page: their fingerprints against the JVM's and Node's. */
  private def assertPlatformFingerprints(): Unit =
    for (name, (classic, soft)) <- PlatformHashesSpec.Expected do
      assert(script(s"return window.simsPlayground.run('$name', 'ClassicStep', ${PlatformHashesSpec.Steps})") == classic,
        s"$name, ClassicStep")
      assert(script(s"return window.simsPlayground.run('$name', 'SoftStep', ${PlatformHashesSpec.Steps})") == soft,
        s"$name, SoftStep")
    assertNoConsoleErrors()

  test("five scenes after 600 steps under each step: Chromium's fingerprints are the JVM's and Node's"):
    assertPlatformFingerprints()

  test("the page runs SiMS linked to WebAssembly; asked for JavaScript, the JavaScript bundle, with the same fingerprints"):
    assert(script("return window.simsPlayground.state().linkedTo") == "WebAssembly")
    assert(element("info").getText.contains("(WebAssembly)"))
    open("index.html?javascript")
    assert(script("return window.simsPlayground.state().linkedTo") == "JavaScript")
    assertPlatformFingerprints()
