package sims.examples.headless

import java.io.PrintStream

/** A one-line progress bar: simulated time of the total and steps per second. On a terminal
  * the line is redrawn in place with a carriage return; otherwise (a CI log) a plain line is
  * printed at every tenth of the run, so logs stay short and readable.
  *
  * @param total       simulated seconds of the whole run
  * @param interactive redraw in place (true on a terminal)
  */
final class ProgressBar(total: Double, out: PrintStream, interactive: Boolean):
  private val width = 30
  private var lastTenth = -1
  private var lastDrawNanos = 0L

  /** Shows the progress at simulated `time` after `steps` steps that took `stepNanos` in all. */
  def update(time: Double, steps: Long, stepNanos: Long): Unit =
    val fraction = if total <= 0 then 1.0 else math.min(1.0, time / total)
    if interactive then
      val now = System.nanoTime()
      // Redrawing at most 20 times a second keeps the terminal from slowing the run.
      if now - lastDrawNanos > 50_000_000L || fraction >= 1.0 then
        lastDrawNanos = now
        out.print("\r" + line(fraction, time, steps, stepNanos))
        out.flush()
    else
      val tenth = (fraction * 10).toInt
      if tenth > lastTenth then
        lastTenth = tenth
        out.println(line(fraction, time, steps, stepNanos))

  /** Ends the bar's line. */
  def finish(): Unit = if interactive then out.println()

  /** The text of the bar. */
  def line(fraction: Double, time: Double, steps: Long, stepNanos: Long): String =
    val filled = math.round(fraction * width).toInt
    val bar = "#" * filled + "." * (width - filled)
    val perSecond = if stepNanos == 0 then 0.0 else steps * 1e9 / stepNanos
    f"[$bar] ${time}%6.2f / ${total}%.2f s  ${perSecond}%8.0f steps/s"

/** Choice of the bar's mode. */
object ProgressBar:
  /** True when standard output is a terminal (no redirection, not a CI log). Under
    * `sbt run` the forked process has no console, so sbt tells it through the system
    * property `sims.examples.terminal`.
    */
  def stdoutIsTerminal: Boolean =
    sys.props.get("sims.examples.terminal").map(_.toBoolean).getOrElse(System.console() != null)
