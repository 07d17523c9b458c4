package sims.bench

import sims.solver.ContactSolver

/** Where a SiMS step spends its time, without JMH: for each scene given, the warm-up steps,
  * a snapshot, and then the same step replayed from that snapshot again and again, so that
  * every repetition does exactly the same work. Prints the best of `--rounds` rounds (default
  * 7) of `--reps` repetitions (default 20) for:
  *   - step: the whole step;
  *   - detect: the broadphase and first narrowphase (`detector.detect()`);
  *   - velocity: loading the contacts and their ten velocity iterations (phase 4 without
  *     joints);
  *   - position: the step minus the same step with position correction off (phase 6);
  * and the step's contact points, their waves (see `sims.solver.WaveOrder`) and the
  * candidate pairs by shape classes.
  * A restore moves every body, so the narrowphase's caches start each repetition empty: the
  * figures are a little above a step's in a running scene. For development; the committed
  * figures come from [[RunAll]].
  */
object Phases:
  def main(args: Array[String]): Unit =
    var reps = 20
    var rounds = 7
    val scenes = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--reps" => reps = it.next().toInt
        case "--rounds" => rounds = it.next().toInt
        case scene => scenes += scene
    val chosen = scenes.result()
    if chosen.isEmpty then println("usage: Phases [--reps N] [--rounds N] scene...; scenes: " + Settings.names.mkString(" "))
    for scene <- chosen do
      val world = SimsBuilder.world(Settings.scene(scene))
      for _ <- 0 until Settings.WarmUpSteps do world.step()
      val state = world.snapshot()
      def best(body: => Unit): Double =
        var fastest = Double.PositiveInfinity
        for _ <- 0 until rounds do
          val start = System.nanoTime()
          for _ <- 0 until reps do body
          fastest = math.min(fastest, (System.nanoTime() - start) / 1e6 / reps)
        fastest
      def replayStep(): Unit =
        world.restore(state)
        world.step()
      val step = best(replayStep())
      world.enablePositionCorrection = false
      val withoutPosition = best(replayStep())
      world.enablePositionCorrection = true
      val detect = best { world.restore(state); world.detector.detect() }
      val solver = ContactSolver()
      world.restore(state)
      world.detector.detect() // the step's collisions, loaded anew in every repetition
      val velocity = best {
        world.restore(state)
        solver.load(world.detector.collisions)
        for _ <- 0 until world.iterations do solver.correctVelocities(world.timeStep)
      }
      world.restore(state)
      val kinds = world.detector match
        case grid: sims.collision.GridDetector =>
          grid.candidatePairs.groupMapReduce((a, b) => s"${a.getClass.getSimpleName}-${b.getClass.getSimpleName}")(_ => 1)(_ + _)
            .toSeq.sorted.map((k, n) => s"$n $k").mkString(", ")
        case _ => ""
      println(f"$scene%-14s step $step%8.3f  detect $detect%8.3f  velocity $velocity%8.3f  " +
        f"position ${step - withoutPosition}%8.3f ms")
      println(s"  ${solver.size} contact points in ${solver.waveCount} waves; candidate pairs: $kinds")
