package sims.bench

import sims.solver.SoftStep

/** Whether the stacked scenes stand under the soft step: for each scene given (default
  * `pyramid-50` and `large_pyramid`), `--seconds S` of simulated time (default 10), then the
  * largest distance of a free body from its start and the largest speed, with the step's mean
  * time. Sleeping is off, as in the bench (`--sleep` turns it on, as the soft step's default).
  * `--trace N` prints, every N steps, the box farthest from its start (where it started, how far
  * it moved across and up) and the highest box's drop. For development.
  */
object Stand:
  def main(args: Array[String]): Unit =
    var seconds = 10.0
    var sleep = false
    var trace = 0
    var solver = SoftStep()
    val scenes = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--seconds" => seconds = it.next().toDouble
        case "--sleep" => sleep = true
        case "--trace" => trace = it.next().toInt
        case "--persistence" => solver = solver.copy(contactPersistence = it.next().toDouble)
        case "--load-depth" => solver = solver.copy(contactLoadDepth = it.next().toDouble)
        case "--hertz" => solver = solver.copy(contactHertz = it.next().toDouble)
        case "--damping" => solver = solver.copy(contactDampingRatio = it.next().toDouble)
        case "--substeps" => solver = solver.copy(substeps = it.next().toInt)
        case "--contact-speed" => solver = solver.copy(contactSpeed = it.next().toDouble)
        case "--speculative" => solver = solver.copy(speculativeDistance = it.next().toDouble)
        case scene => scenes += scene
    val chosen = Some(scenes.result()).filter(_.nonEmpty).getOrElse(Seq("pyramid-50", "large_pyramid"))
    println(solver)
    for name <- chosen do
      val scene = Settings.scene(name)
      val world = SimsBuilder.world(scene, solver)
      world.enableSleep = sleep
      val free = world.bodies.filterNot(_.fixed).toIndexedSeq
      val start = free.map(b => (b.x, b.y))
      val steps = math.round(seconds / world.timeStep).toInt
      val began = System.nanoTime()
      val top = free.indices.maxBy(start(_)._2)
      for step <- 1 to steps do
        world.step()
        if trace > 0 && step % trace == 0 then
          val far = free.indices.maxBy(i => math.hypot(free(i).x - start(i)._1, free(i).y - start(i)._2))
          val (x0, y0) = start(far)
          println(f"  step $step%5d  farthest: box $far%4d from ($x0%.2f, $y0%.2f) moved ${(free(far).x - x0) * 100}%+.2f cm across " +
            f"${(free(far).y - y0) * 100}%+.2f cm up;  top box ${(free(top).y - start(top)._2) * 100}%+.2f cm up;  speed max " +
            f"${free.map(b => math.hypot(b.vx, b.vy)).max}%.3f m/s")
      val ms = (System.nanoTime() - began) / 1e6 / steps
      val drift = free.indices.map(i => math.hypot(free(i).x - start(i)._1, free(i).y - start(i)._2))
      val speed = free.map(b => math.hypot(b.vx, b.vy))
      val worst = drift.indices.maxBy(drift)
      println(
        f"$name%-16s ${free.size}%5d boxes  drift max ${drift.max * 100}%.2f cm (box $worst%d) mean ${drift.sum / drift.size * 100}%.3f cm  speed max ${speed.max}%.4f m/s  $ms%.2f ms/step")
