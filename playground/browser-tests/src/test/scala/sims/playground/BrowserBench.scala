package sims.playground

import java.io.File
import java.nio.file.Files
import java.time.Duration
import org.openqa.selenium.support.ui.WebDriverWait
import scala.jdk.CollectionConverters.*

/** Runs the browser benchmark page (`benchPage/staticSite`) in headless Chromium and writes its
  * table into the "Browser" section of docs/src/performance.md. Arguments: the page's folder and
  * the performance document. Run with `./sbt browserTests/browserBench`.
  */
object BrowserBench:
  /** One engine on one scene: ms per step and the sanity check after the run. */
  final case class Row(scene: String, engine: String, millis: Double, ok: Boolean, detail: String)

  /** The soft step linked to JavaScript and to WebAssembly: the rows compared with the peers. */
  private val Softs = Seq("SiMS SoftStep", "SiMS SoftStep Wasm")

  def main(args: Array[String]): Unit =
    require(args.length == 2, "arguments: the bench page's folder and docs/src/performance.md")
    require(Chromium.installed, "Chromium is not installed (apt-get install chromium chromium-driver)")
    val chromium = Chromium.open(File(args(0)))
    try
      chromium.driver.get(chromium.address("index.html"))
      // The page is busy between its pauses (a chunk of steps of a big scene on a loaded
      // machine can take long): a poll that times out is tried again.
      chromium.driver.manage().timeouts().scriptTimeout(Duration.ofMinutes(2))
      val wait = WebDriverWait(chromium.driver, Duration.ofMinutes(30))
      wait.ignoring(classOf[org.openqa.selenium.ScriptTimeoutException])
      wait.ignoring(classOf[org.openqa.selenium.TimeoutException])
      val results = wait.until { d =>
        chromium.driver.executeScript("return window.benchResults || null")
      }.asInstanceOf[java.util.Map[String, AnyRef]].asScala
      results.get("error").foreach(e => sys.error(s"the bench page failed: $e"))
      val rows = results("results").asInstanceOf[java.util.List[java.util.Map[String, AnyRef]]].asScala.toSeq.map { r =>
        Row(r.get("scene").toString, r.get("engine").toString, r.get("millis").asInstanceOf[Number].doubleValue,
          r.get("ok") == java.lang.Boolean.TRUE, r.get("detail").toString)
      }
      val errors = chromium.consoleErrors()
      require(errors.isEmpty, s"console errors: ${errors.mkString("; ")}")
      val clockStep = results("clockStepMillis").asInstanceOf[Number].doubleValue
      val section = markdown(rows, results("codeWarmUpMillis").toString, results("warmUpSteps").toString,
        results("timedSteps").toString,
        results("userAgent").toString, clockStep)
      println(section)
      val document = File(args(1)).toPath
      Files.writeString(document, withSection(Files.readString(document), section))
    finally chromium.close()

  /** The document with its "## Browser" section replaced by `section` (added at the end if none). */
  def withSection(document: String, section: String): String =
    val start = document.indexOf("\n## Browser\n")
    if start < 0 then document.stripSuffix("\n") + "\n\n" + section
    else
      val next = document.indexOf("\n## ", start + 1)
      document.substring(0, start + 1) + section + (if next < 0 then "" else document.substring(next))

  private[playground] def markdown(rows: Seq[Row], codeWarmUp: String, warmUp: String, timed: String, agent: String,
      clockStep: Double): String =
    val engines = rows.map(_.engine).distinct
    val scenes = rows.map(_.scene).distinct
    def row(scene: String, engine: String): Option[Row] = rows.find(r => r.scene == scene && r.engine == engine)
    def cell(scene: String, engine: String): String =
      row(scene, engine).fold("")(r => f"${r.millis}%.3f" + (if r.ok then "" else " (insane)"))
    def millis(scene: String, engine: String): Option[Double] = row(scene, engine).map(_.millis)
    // The soft step is the solver to compare: the classic step fails the checks on most scenes.
    def ratio(scene: String, soft: String, peer: String): Option[Double] =
      for time <- millis(scene, soft); other <- millis(scene, peer) yield time / other
    val softs = Softs.filter(engines.contains)
    val peers = engines.filterNot(_.startsWith("SiMS"))
    val pairs = for soft <- softs; peer <- peers yield (soft, peer)
    val header = s"| scene | ${engines.mkString(" | ")} |\n|---|${engines.map(_ => "---:").mkString("|")}|\n"
    val body = scenes.map(s => s"| $s | ${engines.map(cell(s, _)).mkString(" | ")} |").mkString("\n")
    val ratios =
      s"| scene | ${pairs.map((soft, p) => s"$soft / $p").mkString(" | ")} |\n|---|${pairs.map(_ => "---:").mkString("|")}|\n" +
        scenes.map(s => s"| $s | ${pairs.map((soft, p) => ratio(s, soft, p).fold("")(r => f"$r%.2f")).mkString(" | ")} |")
          .mkString("\n")
    // What the figures say of the aims: faster than the JavaScript engines, within 1.5 times Rapier's WebAssembly.
    def aim(soft: String)(peer: String, bound: Double, wanted: String): String =
      scenes.filter(s => ratio(s, soft, peer).exists(_ > bound)) match
        case Seq() => s"$wanted $peer on every scene"
        case missed => s"not $wanted $peer on ${missed.mkString(", ")}"
    val aims = Seq(("planck", 1.0, "faster than"), ("matter-js", 1.0, "faster than"), ("Rapier", 1.5, "within 1.5 times"))
    val summary = softs.map(soft => s"$soft is " + aims.filter((peer, _, _) => peers.contains(peer)).map(aim(soft)).mkString("; "))
      .mkString(". ")
    val sanity = rows.map(r => s"| ${r.scene} | ${r.engine} | ${if r.ok then "ok" else "failed"} | ${r.detail} |").mkString("\n")
    // The tables go in after stripMargin, which would take the pipe off the start of their rows.
    s"""## Browser
       |
       |The bench scenes in headless Chromium (`./sbt browserTests/browserBench`, which builds the
       |page of `bench/browser` and writes this section): SiMS compiled with Scala.js (fullLinkJS),
       |both steps linked to JavaScript and the soft step linked to WebAssembly too ("SiMS SoftStep
       |Wasm": the same sources, the same bits, by Scala.js's WebAssembly backend, see "SiMS in
       |WebAssembly" below), and in the same page planck 1.5.0, matter-js 0.20.0 and Rapier (`@dimforge/rapier2d-compat`
       |0.21.0, Rust compiled to WebAssembly), each from npm, each building the scene from the same
       |layout values. Every engine first steps a copy of the scene for $codeWarmUp ms, thrown away, so
       |that the browser has compiled its code to its fastest (as the JVM bench's warm-up does), then
       |builds the scene again and runs $warmUp steps before $timed timed steps, the engines of a scene
       |taking turns of 10 steps (the order rotating from turn to turn, so that a change in the
       |machine's load falls on all of them alike) and each one's time the median of its turns; planck and
       |matter-js with 10 velocity and 10 position iterations as in the JVM bench, Rapier with its
       |defaults; sleeping off. The page is cross-origin isolated, so its clock reads in steps of
       |@clock@ µs (0.1 ms otherwise): a turn's time is that fine. The sanity check after the run is the JVM bench's (a pyramid stands,
       |a chain's joints hold their length within 25%, the balls stay in their pit); a result whose
       |check failed is marked "insane". The machine is shared and noisy: the ratios come from one
       |run and only they compare. Browser: $agent.
       |
       |Milliseconds per step:
       |
       |@times@
       |
       |The soft step's time over each peer's, in JavaScript and in WebAssembly (below 1: SiMS is faster):
       |
       |@ratios@
       |
       |In this run @summary@.
       |
       |Sanity after the run:
       |
       || scene | engine | sanity | measured |
       ||---|---|---|---|
       |@sanity@
       |""".stripMargin.replace("@times@", header + body).replace("@ratios@", ratios).replace("@summary@", summary).replace(
      "@clock@", f"${clockStep * 1000}%.1f").replace(
      "@sanity@", sanity)
