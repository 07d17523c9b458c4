package sims.bench

/** A quick look without JMH: for each scene given (default: all but the two largest ballpits)
  * and each engine, the warm-up steps, then `--steps N` timed steps (default 100), the mean
  * time per step and the sanity check. For development; the committed figures come from
  * [[RunAll]].
  */
object Quick:
  def main(args: Array[String]): Unit =
    var steps = 100
    var engines: Seq[Engine] = Engine.values.toSeq
    val scenes = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--steps" => steps = it.next().toInt
        case "--engine" => engines = Seq(Engine.named(it.next()))
        case scene => scenes += scene
    val chosen = Some(scenes.result()).filter(_.nonEmpty)
      .getOrElse(Settings.names.filterNot(n => n == "ballpit-8000" || n == "ballpit-16000"))
    for name <- chosen; scene = Settings.scene(name); engine <- Engine.forScene(scene) if engines.contains(engine) do
      val built = engine.build(scene)
      for _ <- 0 until Settings.WarmUpSteps do built.step()
      val start = System.nanoTime()
      for _ <- 0 until steps do built.step()
      val ms = (System.nanoTime() - start) / 1e6 / steps
      val sanity = Sanity.check(scene, built)
      println(f"$name%-14s ${engine.label}%-9s $ms%9.3f ms/step  sane=${sanity.ok}%-5s ${sanity.detail}")
