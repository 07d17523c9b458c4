package sims.bench

import sims.solver.SoftStep

/** The soft step's speed-up from its worker threads, without JMH: for each scene given, one world
  * per worker count (1 and `--workers`, default 2) stepped through the warm-up, then in
  * alternation `--reps` steps each (default 5), `--rounds` times (default 9), so that both meet
  * the same load of a shared machine; both do the same work, their states the same bits at
  * every step. Prints the mean time of a step over all rounds for each, their ratio, the serial fraction that
  * ratio implies (Karp-Flatt: f = (N / S - 1) / (N - 1)) and what Amdahl's law gives with it on 8
  * and 16 cores. Usage: `./sbt "bench/runMain sims.bench.WorkersSpeedup ballpit-16000 large_pyramid"`.
  */
object WorkersSpeedup:
  def main(args: Array[String]): Unit =
    var reps = 5
    var rounds = 9
    var workers = 2
    val scenes = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--reps" => reps = it.next().toInt
        case "--rounds" => rounds = it.next().toInt
        case "--workers" => workers = it.next().toInt
        case scene => scenes += scene
    for scene <- scenes.result() do
      val worlds = Seq(1, workers).map { n =>
        val world = SimsBuilder.world(Settings.scene(scene))
        world.solver = SoftStep(workers = n)
        for _ <- 0 until Settings.WarmUpSteps do world.step()
        world
      }
      val best = Array.fill(2)(0.0)
      for _ <- 0 until rounds; k <- 0 until 2 do
        val world = worlds(k)
        val start = System.nanoTime()
        for _ <- 0 until reps do world.step()
        best(k) += (System.nanoTime() - start) / 1e6 / reps / rounds
      val speedup = best(0) / best(1)
      val serial = (workers / speedup - 1) / (workers - 1)
      def amdahl(cores: Int) = 1 / (serial + (1 - serial) / cores)
      println(f"$scene%-16s 1 worker ${best(0)}%8.2f ms, $workers workers ${best(1)}%8.2f ms: ${speedup}%.2fx; " +
        f"serial fraction ${serial * 100}%.1f%%, Amdahl 8 cores ${amdahl(8)}%.1fx, 16 cores ${amdahl(16)}%.1fx")
