package sims.bench

/** Formats the benchmark results as Markdown. */
object Report:
  private def ms(us: Double): String = if us.isNaN then "-" else f"${us / 1000}%.3f"
  private def msError(us: Double, error: Double): String =
    if us.isNaN then "-" else if error.isNaN then ms(us) else f"${us / 1000}%.3f ± ${error / 1000}%.3f"
  private def bytes(b: Double): String = if b.isNaN then "-" else f"$b%.0f"

  /** The report: settings, one table of times and allocation (SiMS's two solvers beside the
    * peers, each solver's ratio to the faster peer), one of sanity.
    */
  def markdown(rows: Seq[RunAll.Row], box2d: Map[String, Double], date: String, forks: Int, warmup: Int,
      iterations: Int, minutes: Double): String =
    val sb = StringBuilder()
    val runtime = Runtime.getRuntime
    sb ++= s"# Step time, SiMS (classic and soft step) vs jBox2D 2.2.1.1 vs dyn4j 5.0.2 ($date)\n\n"
    sb ++= s"Machine: ${runtime.availableProcessors} cores, ${System.getProperty("os.name")} ${System.getProperty("os.arch")}, " +
      s"Java ${System.getProperty("java.version")} (${System.getProperty("java.vm.name")}).\n"
    sb ++= s"JMH: average time per step after ${Settings.WarmUpSteps} warm-up steps, $forks fork(s), " +
      s"$warmup x 1 s warm-up and $iterations x 1 s measurement iterations, GC profiler; " +
      f"all engines in one run ($minutes%.1f min).\n"
    sb ++= "Settings: gravity (0, -9.81), dt 1/60, 10 velocity and 10 position iterations, friction 0.5, " +
      "restitution 0, density 1; sleeping and continuous collision detection off in the peers. " +
      "SiMS is the classic step (SiMS 1.2's, the default); SiMS-soft is `SoftStep(workers = 1)`, the soft step " +
      "with its defaults on one thread as the peers run (it ignores the iterations); SiMS-soft-workers is " +
      s"`SoftStep()`, all ${runtime.availableProcessors} processors, on the scenes of 4,000 bodies or more.\n\n"
    sb ++= "Times in ms per step (± the JMH 99.9% error); allocation in bytes per step; " +
      "ratio = the SiMS solver's time / the faster peer's time.\n\n"
    sb ++= "| scene | SiMS ms | SiMS-soft ms | jBox2D ms | dyn4j ms | SiMS / faster peer | SiMS-soft / faster peer " +
      "| SiMS B/step | SiMS-soft B/step | jBox2D B/step | dyn4j B/step |\n"
    sb ++= "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
    val scenes = rows.map(_.scene).distinct
    def find(scene: String, engine: Engine) = rows.find(r => r.scene == scene && r.engine == engine.label)
    for scene <- scenes do
      val peers = Engine.peers.flatMap(find(scene, _)).map(_.microseconds)
      def ratio(r: Option[RunAll.Row]) = r match
        case Some(x) if peers.nonEmpty => f"${x.microseconds / peers.min}%.3f"
        case _ => "-"
      def t(r: Option[RunAll.Row]) = r.map(x => msError(x.microseconds, x.error)).getOrElse("-")
      def a(r: Option[RunAll.Row]) = r.map(x => bytes(x.bytesPerStep)).getOrElse("-")
      val ordered = Seq(Engine.Sims, Engine.SimsSoft, Engine.JBox2D, Engine.Dyn4j).map(find(scene, _))
      val ratios = Engine.sims.map(e => ratio(find(scene, e)))
      sb ++= s"| $scene | ${ordered.map(t).mkString(" | ")} | ${ratios.mkString(" | ")} | ${ordered.map(a).mkString(" | ")} |\n"
    val big = scenes.filter(scene => box2d.contains(scene) || find(scene, Engine.SimsSoftWorkers).nonEmpty)
    if big.nonEmpty then
      sb ++= s"\nThe soft step with ${runtime.availableProcessors} workers, and Box2D v3 (C, one thread, measured in the same " +
        "run by its own build: the bench's scenes written with its API, its own benchmark program for its scenes; " +
        "ratio below 1: SiMS is faster):\n\n"
      sb ++= "| scene | SiMS-soft ms | SiMS-soft-workers ms | speedup | Box2D v3 ms | SiMS-soft / Box2D v3 | " +
        "SiMS-soft-workers / Box2D v3 |\n|---|---:|---:|---:|---:|---:|---:|\n"
      for scene <- big do
        val one = find(scene, Engine.SimsSoft).map(_.microseconds)
        val all = find(scene, Engine.SimsSoftWorkers).map(_.microseconds)
        val c = box2d.get(scene).map(_ * 1000)
        def cell(us: Option[Double]) = us.map(ms).getOrElse("-")
        def over(a: Option[Double], b: Option[Double]) =
          (for x <- a; y <- b yield f"${x / y}%.2f").getOrElse("-")
        sb ++= s"| $scene | ${cell(one)} | ${cell(all)} | ${over(one, all)} | ${cell(c)} | ${over(one, c)} | ${over(all, c)} |\n"
    for engine <- Engine.sims do
      (find("ballpit-16000", engine), find("ballpit-4000", engine)) match
        case (Some(big), Some(small)) =>
          sb ++= f"\n${engine.label} ballpit-16000 / ballpit-4000: ${big.microseconds / small.microseconds}%.2f\n"
        case _ => ()
    sb ++= "\n## Sanity after the run\n\n"
    sb ++= "| scene | engine | sane | steps run | measured |\n|---|---|---|---:|---|\n"
    for scene <- scenes; r <- rows.filter(_.scene == scene) do
      r.sanity match
        case Some((ok, steps, detail)) =>
          sb ++= s"| $scene | ${r.engine} | ${if ok then "yes" else "**no**"} | $steps | $detail |\n"
        case None => sb ++= s"| $scene | ${r.engine} | ? | - | no report |\n"
    sb.result()
