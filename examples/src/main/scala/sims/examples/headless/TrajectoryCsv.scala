package sims.examples.headless

import java.io.{BufferedWriter, File, FileWriter}
import sims.dynamics.World

/** Writes every body's state over time as CSV, one row per body and sample:
  * `time,body,x,y,rotation,vx,vy,angularVelocity` (SI units, body = index in the world).
  */
final class TrajectoryCsv(file: File) extends AutoCloseable:
  private val out = BufferedWriter(FileWriter(file))
  out.write(TrajectoryCsv.Header)
  out.newLine()
  private var rows = 0L

  /** Rows written so far (header not counted). */
  def rowCount: Long = rows

  /** Appends one row per body of `world` at its current time. */
  def sample(world: World): Unit =
    val time = world.time
    val bodies = world.bodies
    val line = StringBuilder()
    var i = 0
    while i < bodies.length do
      val b = bodies(i)
      val p = b.pos
      val v = b.linearVelocity
      line.setLength(0)
      line.append(TrajectoryCsv.format(time)).append(',').append(i)
      for value <- Seq(p.x, p.y, b.rotation, v.x, v.y, b.angularVelocity) do
        line.append(',').append(TrajectoryCsv.format(value))
      out.write(line.toString)
      out.newLine()
      rows += 1
      i += 1

  /** Flushes and closes the file. */
  def close(): Unit = out.close()

/** The CSV layout. */
object TrajectoryCsv:
  /** The first line of every file. */
  val Header = "time,body,x,y,rotation,vx,vy,angularVelocity"

  /** A number with enough digits for plotting, without locale-dependent separators. */
  private def format(value: Double): String = java.lang.String.format(java.util.Locale.ROOT, "%.6g", value)
