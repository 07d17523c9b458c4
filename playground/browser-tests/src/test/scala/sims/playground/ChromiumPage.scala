package sims.playground

import java.io.File
import java.time.Duration
import org.openqa.selenium.support.ui.WebDriverWait
import org.scalatest.{BeforeAndAfterAll, Suite}

/** A suite whose tests use one page of a served folder in headless Chromium: opened before the
  * first test (once the page's script says it is ready), closed after the last. Its tests are
  * canceled where Chromium is not installed.
  */
trait ChromiumPage extends BeforeAndAfterAll:
  this: Suite =>

  /** The folder served. */
  protected def folder: File

  /** The page opened first. */
  protected def page: String

  /** A script expression that is true once the page is ready. */
  protected def ready: String

  private var chromium: Option[Chromium] = None

  /** The browser, for a test (canceled when Chromium is not installed). */
  protected def browser: Chromium =
    assume(Chromium.installed, "Chromium is not installed (apt-get install chromium chromium-driver)")
    chromium.get

  override def beforeAll(): Unit =
    if Chromium.installed then
      chromium = Some(Chromium.open(folder))
      browser.driver.manage().timeouts().scriptTimeout(Duration.ofMinutes(2))
      open(page)

  override def afterAll(): Unit = chromium.foreach(_.close())

  /** Opens `address` (a page of the folder) and waits until it is ready. */
  protected def open(address: String): Unit =
    browser.driver.get(browser.address(address))
    WebDriverWait(browser.driver, Duration.ofSeconds(30)).until(d => script(s"return $ready") == java.lang.Boolean.TRUE)

  /** Runs `code` in the page, with `args` as `arguments`. */
  protected def script(code: String, args: AnyRef*): AnyRef = browser.driver.executeScript(code, args*)

  /** Fails with the page's console errors since the last call, if any. */
  protected def assertNoConsoleErrors(): Unit =
    val errors = browser.consoleErrors()
    assert(errors.isEmpty, errors.mkString("\n"))
