package sims.bench

import sims.solver.SoftStep

/** What more substeps cost the soft step on one thread: the same scene under several
  * `substeps:contactHertz` settings (default `4:30`, the soft step's defaults, `8:120` and
  * `10:150`), each world stepped 300 times, then the worlds stepped in turns of 10 steps for the
  * seconds given, the first setting's world first in one turn and last in another. Prints each
  * setting's median time a step and its ratio to the first's. Wall clock on a shared machine:
  * only the ratios mean anything. For development, beside `Stand`, which says how well the same
  * settings hold the big stacks.
  *
  * Arguments: scene, seconds, then settings (`8:120`).
  */
object SubstepCost:
  def main(args: Array[String]): Unit =
    require(args.length >= 2, "arguments: scene, seconds, then substeps:hertz settings")
    val scene = Settings.scene(args(0))
    val seconds = args(1).toDouble
    val listed = args.drop(2).toSeq
    val settings = (if listed.isEmpty then Seq("4:30", "8:120", "10:150") else listed).map { setting =>
      setting.split(':') match
        case Array(substeps, hertz) => SoftStep(workers = 1, substeps = substeps.toInt, contactHertz = hertz.toDouble)
        case _ => throw IllegalArgumentException(s"a setting is substeps:hertz, got $setting")
    }
    val worlds = settings.map(SimsBuilder.world(scene, _))
    for world <- worlds; _ <- 0 until 300 do world.step()
    val times = IndexedSeq.fill(settings.size)(scala.collection.mutable.ArrayBuffer.empty[Double])
    val end = System.nanoTime() + (seconds * 1e9).toLong
    var turn = 0
    while System.nanoTime() < end do
      for i <- settings.indices do
        val k = (i + turn) % settings.size
        val started = System.nanoTime()
        for _ <- 0 until 10 do worlds(k).step()
        times(k) += (System.nanoTime() - started) / 1e7
      turn += 1
    val medians = times.map(t => t.sorted.apply(t.size / 2))
    for i <- settings.indices do
      println(
        f"${args(0)}%-14s substeps ${settings(i).substeps}%2d, contactHertz ${settings(i).contactHertz}%5.0f: " +
          f"median ${medians(i)}%.3f ms/step, ${medians(i) / medians(0)}%.2f times the first"
      )
