package sims.bench

import sims.solver.SoftStep

/** What a settled scene costs asleep: for each scene given (default `ballpit-4000`), the soft
  * step with sleeping on runs until every body sleeps (at most `--seconds S` of simulated time,
  * default 20), then the mean time of `--steps N` steps (default 300) asleep is compared with
  * the same number of steps of the same settled world with sleeping off (every body awake),
  * alternating the two in rounds so that the machine's load falls on both alike. For
  * development: the wall-clock times are rough, their ratio is what it reports
  * (`--asleep-only` skips the awake steps, to profile the sleeping ones).
  */
object SleepCost:
  def main(args: Array[String]): Unit =
    var seconds = 20.0
    var steps = 300
    var asleepOnly = false // for a profiler: only the steps asleep
    val scenes = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--seconds" => seconds = it.next().toDouble
        case "--steps" => steps = it.next().toInt
        case "--asleep-only" => asleepOnly = true
        case scene => scenes += scene
    val chosen = Some(scenes.result()).filter(_.nonEmpty).getOrElse(Seq("ballpit-4000"))
    for name <- chosen do
      val world = SimsBuilder.world(Settings.scene(name), SoftStep())
      world.enableSleep = true
      val free = world.bodies.count(!_.fixed)
      val limit = math.round(seconds / world.timeStep).toInt
      var settled = 0
      while settled < limit && world.awakeBodyCount > world.bodies.count(_.fixed) do
        world.step()
        settled += 1
      val asleep = free - (world.awakeBodyCount - world.bodies.count(_.fixed))
      val state = world.snapshot()
      def time(sleep: Boolean): Double =
        world.restore(state)
        world.enableSleep = sleep
        if sleep then
          // The snapshot keeps the sleep state: back to it after enableSleep = false woke them.
          world.restore(state)
        val began = System.nanoTime()
        for _ <- 0 until steps do world.step()
        (System.nanoTime() - began) / 1e6 / steps
      var asleepMs = 0.0
      var awakeMs = 0.0
      for _ <- 1 to 3 do
        asleepMs += time(sleep = true)
        if !asleepOnly then awakeMs += time(sleep = false)
      println(f"$name%-16s $asleep%5d of $free%5d bodies asleep after ${settled * world.timeStep}%.2f s; " +
        f"asleep ${asleepMs / 3}%.4f ms/step, awake ${awakeMs / 3}%.3f ms/step: ${asleepMs / awakeMs * 100}%.2f %%")
