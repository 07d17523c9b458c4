package sims.bench

/** Formats the benchmark results as Markdown. */
object Report:
  private def ms(us: Double): String = if us.isNaN then "-" else f"${us / 1000}%.3f"
  private def msError(us: Double, error: Double): String =
    if us.isNaN then "-" else if error.isNaN then ms(us) else f"${us / 1000}%.3f ± ${error / 1000}%.3f"
  private def bytes(b: Double): String = if b.isNaN then "-" else f"$b%.0f"

  /** The report: settings, one table of times and allocation, one of sanity. */
  def markdown(rows: Seq[RunAll.Row], date: String, forks: Int, warmup: Int, iterations: Int,
      minutes: Double): String =
    val sb = StringBuilder()
    val runtime = Runtime.getRuntime
    sb ++= s"# Step time, SiMS vs jBox2D 2.2.1.1 vs dyn4j 5.0.2 ($date)\n\n"
    sb ++= s"Machine: ${runtime.availableProcessors} cores, ${System.getProperty("os.name")} ${System.getProperty("os.arch")}, " +
      s"Java ${System.getProperty("java.version")} (${System.getProperty("java.vm.name")}).\n"
    sb ++= s"JMH: average time per step after ${Settings.WarmUpSteps} warm-up steps, $forks fork(s), " +
      s"$warmup x 1 s warm-up and $iterations x 1 s measurement iterations, GC profiler; " +
      f"all engines in one run ($minutes%.1f min).\n"
    sb ++= "Settings: gravity (0, -9.81), dt 1/60, 10 velocity and 10 position iterations, friction 0.5, " +
      "restitution 0, density 1; sleeping and continuous collision detection off in the peers.\n\n"
    sb ++= "Times in ms per step (± the JMH 99.9% error); allocation in bytes per step; " +
      "ratio = SiMS time / the faster peer's time.\n\n"
    sb ++= "| scene | SiMS ms | jBox2D ms | dyn4j ms | SiMS / faster peer | SiMS B/step | jBox2D B/step | dyn4j B/step |\n"
    sb ++= "|---|---:|---:|---:|---:|---:|---:|---:|\n"
    val scenes = rows.map(_.scene).distinct
    def find(scene: String, engine: Engine) = rows.find(r => r.scene == scene && r.engine == engine.label)
    for scene <- scenes do
      val s = find(scene, Engine.Sims)
      val b = find(scene, Engine.JBox2D)
      val d = find(scene, Engine.Dyn4j)
      val peers = Seq(b, d).flatten.map(_.microseconds)
      val ratio = (s, peers) match
        case (Some(x), ps) if ps.nonEmpty => f"${x.microseconds / ps.min}%.3f"
        case _ => "-"
      def t(r: Option[RunAll.Row]) = r.map(x => msError(x.microseconds, x.error)).getOrElse("-")
      def a(r: Option[RunAll.Row]) = r.map(x => bytes(x.bytesPerStep)).getOrElse("-")
      sb ++= s"| $scene | ${t(s)} | ${t(b)} | ${t(d)} | $ratio | ${a(s)} | ${a(b)} | ${a(d)} |\n"
    (find("ballpit-16000", Engine.Sims), find("ballpit-4000", Engine.Sims)) match
      case (Some(big), Some(small)) =>
        sb ++= f"\nSiMS ballpit-16000 / ballpit-4000: ${big.microseconds / small.microseconds}%.2f\n"
      case _ => ()
    sb ++= "\n## Sanity after the run\n\n"
    sb ++= "| scene | engine | sane | steps run | measured |\n|---|---|---|---:|---|\n"
    for scene <- scenes; r <- rows.filter(_.scene == scene) do
      r.sanity match
        case Some((ok, steps, detail)) =>
          sb ++= s"| $scene | ${r.engine} | ${if ok then "yes" else "**no**"} | $steps | $detail |\n"
        case None => sb ++= s"| $scene | ${r.engine} | ? | - | no report |\n"
    sb.result()
