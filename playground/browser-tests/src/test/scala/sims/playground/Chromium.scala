package sims.playground

import java.io.File
import java.net.InetSocketAddress
import java.nio.file.{Files, Path}
import com.sun.net.httpserver.HttpServer
import org.openqa.selenium.chrome.{ChromeDriver, ChromeDriverService, ChromeOptions}
import org.openqa.selenium.logging.{LogType, LoggingPreferences}
import scala.jdk.CollectionConverters.*

/** Headless Chromium (Debian's `chromium` and `chromium-driver`) driven by Selenium, on pages
  * served from a folder by a web server on the loopback address only (a module page cannot be
  * opened from a file). The machine has no network: Chromium's own background connections
  * (updates, sync, QUIC) are switched off, and its profile is a fresh folder each time.
  */
final class Chromium private (val driver: ChromeDriver, server: HttpServer, profile: Path):
  /** The address of `page` in the served folder. */
  def address(page: String): String = s"http://127.0.0.1:${server.getAddress.getPort}/$page"

  /** The console's errors (and uncaught exceptions) since the last call. */
  def consoleErrors(): Seq[String] =
    driver.manage().logs().get(LogType.BROWSER).getAll.asScala.toSeq
      .filter(_.getLevel.intValue >= java.util.logging.Level.SEVERE.intValue).map(_.getMessage)

  /** Quits the browser, stops the server and removes the profile. */
  def close(): Unit =
    try driver.quit()
    finally
      server.stop(0)
      Files.walk(profile).sorted(java.util.Comparator.reverseOrder()).forEach(p => Files.deleteIfExists(p))

object Chromium:
  val Binary: File = File("/usr/bin/chromium")
  val Driver: File = File("/usr/bin/chromedriver")

  /** Whether Chromium and its driver are installed (else the browser tests are canceled). */
  def installed: Boolean = Binary.canExecute && Driver.canExecute

  /** Serves `folder` on 127.0.0.1 and opens a headless Chromium of window size 1000 x 1000. */
  def open(folder: File): Chromium =
    val server = HttpServer.create(InetSocketAddress("127.0.0.1", 0), 0)
    server.createContext("/",
      exchange => {
        val relative = exchange.getRequestURI.getPath.stripPrefix("/")
        val file = File(folder, if relative.isEmpty then "index.html" else relative).getCanonicalFile
        if file.isFile && file.getPath.startsWith(folder.getCanonicalPath) then
          val bytes = Files.readAllBytes(file.toPath)
          val name = file.getName
          val kind =
            if name.endsWith(".html") then "text/html; charset=utf-8"
            else if name.endsWith(".js") || name.endsWith(".mjs") then "text/javascript"
            else if name.endsWith(".wasm") then "application/wasm"
            else "application/octet-stream"
          exchange.getResponseHeaders.add("Content-Type", kind)
          // Cross-origin isolated (every resource is the server's own): the page's clock then
          // reads in microseconds, not in the tenth of a millisecond it is coarsened to otherwise.
          exchange.getResponseHeaders.add("Cross-Origin-Opener-Policy", "same-origin")
          exchange.getResponseHeaders.add("Cross-Origin-Embedder-Policy", "require-corp")
          exchange.sendResponseHeaders(200, bytes.length)
          exchange.getResponseBody.write(bytes)
        else exchange.sendResponseHeaders(404, -1)
        exchange.close()
      })
    server.start()
    val profile = Files.createTempDirectory("sims-chromium-")
    val options = ChromeOptions()
    options.setBinary(Binary)
    options.addArguments("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
      "--disable-background-networking", "--disable-component-update", "--disable-sync",
      "--disable-dev-shm-usage", s"--user-data-dir=$profile", "--window-size=1000,1000")
    val logging = LoggingPreferences()
    logging.enable(LogType.BROWSER, java.util.logging.Level.ALL)
    options.setCapability("goog:loggingPrefs", logging)
    val service = ChromeDriverService.Builder().usingDriverExecutable(Driver).usingAnyFreePort().build()
    try Chromium(ChromeDriver(service, options), server, profile)
    catch
      case e: Throwable =>
        server.stop(0)
        throw e
