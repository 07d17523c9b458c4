package sims.bench

import java.nio.file.{Files, Path}
import sims.dynamics.World
import sims.scenes.{Ballpit, BoxPyramid, BoxStack, Drop, HeavyStack, Layout, Outline, Scene, SwingingChain}

/** The quality report of the soft step: the same scenes in every engine (SiMS with
  * the classic step, SiMS with `SoftStep()`, jBox2D, dyn4j), each with its defaults at 60 Hz and
  * the bench's settings, measured by the same code, and whether the soft step meets the
  * issue's targets. Prints one Markdown table and writes it to `bench/results/quality-<date>.md`.
  *
  * Arguments (all optional): trial names to run only those (`pyramid-20`, `stack-12`,
  * `chain-100`, `ballpit-2000`, `ballpit-4000`, `heavy-stack`, `drop-e1`, `drop-e0.5`,
  * `drop-e0`, `determinism`); `--out FILE` (relative to the repository's root).
  */
object Quality:
  /** The engines of the report, in the order of its columns. */
  val Engines: Seq[Engine] = Seq(Engine.Sims, Engine.SimsSoft, Engine.JBox2D, Engine.Dyn4j)

  /** One number a trial measures, with the soft step's target for it.
    *
    * @param name what is measured, with its unit
    * @param target the target as the report prints it ("-" when there is none)
    * @param meets whether a value meets the target (values of one measure: usually one)
    * @param show how a value is printed
    */
  final case class Measure(name: String, target: String, meets: IndexedSeq[Double] => Boolean, show: Double => String)

  /** What one engine gave in a trial: the values of each measure, in order, and the mean wall
    * time of a step (NaN when the trial does not time its steps).
    */
  final case class Outcome(values: IndexedSeq[IndexedSeq[Double]], millisPerStep: Double)

  /** A scene run in every engine and measured the same way. */
  trait Trial:
    /** The trial's name (its scene's, or `determinism`). */
    def name: String
    /** What it measures, in the order of [[Outcome.values]]. */
    def measures: Seq[Measure]
    /** Runs the trial in one engine. */
    def run(engine: Engine): Outcome

  /** One line of the report's table. */
  final case class Line(trial: String, measure: String, target: String, cells: Seq[String], softMeets: Option[Boolean])

  // ---- Formats and tests of values

  private def fixed(digits: Int)(value: Double): String =
    if value.isNaN then "-"
    else if math.abs(value) >= 1e4 then f"$value%.3g"
    else s"%.${digits}f".format(value)
  private def count(value: Double): String = if value.isNaN then "-" else f"$value%.0f"
  private def yesNo(value: Double): String = if value.isNaN then "-" else if value == 1 then "yes" else "no"
  private def below(limit: Double)(values: IndexedSeq[Double]): Boolean = values.forall(_ < limit)
  private def atMost(limit: Double)(values: IndexedSeq[Double]): Boolean = values.forall(_ <= limit)
  private def atLeast(limit: Double)(values: IndexedSeq[Double]): Boolean = values.forall(_ >= limit)
  private val yes: IndexedSeq[Double] => Boolean = _.forall(_ == 1)

  /** The angle's distance from upright (0 modulo a full turn), rad: a box on its side is 1.57 off. */
  private def tilt(angle: Double): Double = math.abs(math.IEEEremainder(angle, 2 * math.Pi))

  /** The free bodies' initial centres, in the order of the engines' states. */
  private def initialCentres(layout: Layout) = layout.freeBodies.map(layout.bodies(_).centre)

  /** Builds the scene in the engine and steps it `steps` times, calling `observe` with the
    * step's number (1 for the first) after each; returns the built scene and the mean wall
    * time of a step, ms (steps alone, not the observation).
    */
  private def simulate(engine: Engine, scene: Scene, steps: Int)(observe: (Int, EngineScene) => Unit): (EngineScene, Double) =
    val built = engine.build(scene)
    var nanos = 0L
    var i = 1
    while i <= steps do
      val start = System.nanoTime()
      built.step()
      nanos += System.nanoTime() - start
      observe(i, built)
      i += 1
    (built, nanos / 1e6 / steps)

  private def stepsOf(layout: Layout, seconds: Double): Int = math.round(seconds / layout.timeStep).toInt

  // ---- The trials

  /** pyramid-20 after 10 s: mean box height as % of the start, the top box's drop, the fastest box. */
  object Pyramid extends Trial:
    private val scene = BoxPyramid(20)
    val name: String = scene.name
    val measures: Seq[Measure] = Seq(
      Measure("mean box height after 10 s, % of the start", ">= 98", atLeast(98), fixed(1)),
      Measure("top box drop after 10 s, m", "< 0.05", below(0.05), fixed(3)),
      Measure("fastest box after 10 s, m/s", "< 0.1", below(0.1), fixed(3)))
    def run(engine: Engine): Outcome =
      val layout = scene.layout
      val initial = initialCentres(layout)
      val (built, ms) = simulate(engine, scene, stepsOf(layout, 10))((_, _) => ())
      val states = built.dynamicStates
      val velocities = built.dynamicVelocities
      val top = initial.length - 1
      val mean = 100 * initial.indices.map(i => states(3 * i + 1)).sum / initial.map(_.y).sum
      val fastest = initial.indices.map(i => math.hypot(velocities(3 * i), velocities(3 * i + 1))).max
      Outcome(IndexedSeq(IndexedSeq(mean), IndexedSeq(initial(top).y - states(3 * top + 1)), IndexedSeq(fastest)), ms)

  /** stack-12 over 30 s: the top box's largest sideways move, the largest tilt of any box. */
  object Stack extends Trial:
    private val scene = BoxStack(12)
    val name: String = scene.name
    val measures: Seq[Measure] = Seq(
      Measure("top box's largest sideways move in 30 s, m", "< 0.1", below(0.1), fixed(4)),
      Measure("largest tilt of any box in 30 s, rad", "<= 0.05", atMost(0.05), fixed(4)))
    def run(engine: Engine): Outcome =
      val initial = initialCentres(scene.layout)
      val top = initial.length - 1
      var sideways = 0.0
      var largestTilt = 0.0
      val (_, ms) = simulate(engine, scene, stepsOf(scene.layout, 30)) { (_, built) =>
        val states = built.dynamicStates
        sideways = math.max(sideways, math.abs(states(3 * top) - initial(top).x))
        for i <- initial.indices do largestTilt = math.max(largestTilt, tilt(states(3 * i + 2)))
      }
      Outcome(IndexedSeq(IndexedSeq(sideways), IndexedSeq(largestTilt)), ms)

  /** chain-100 over the last second of 10 s: the largest total stretch of the links together
    * (the sum of every link's |length - rest length|) and the largest of a single link.
    */
  object Chain extends Trial:
    private val scene = SwingingChain(100)
    val name: String = scene.name
    val measures: Seq[Measure] = Seq(
      Measure("largest total stretch of the 99 links, last second of 10 s, m", "< 0.5", below(0.5), fixed(3)),
      Measure("largest stretch of one link, last second of 10 s, cm", "< 1", below(1), fixed(2)))
    def run(engine: Engine): Outcome =
      val layout = scene.layout
      val rest = layout.joints.map(layout.length)
      val steps = stepsOf(layout, 10)
      val lastSecond = steps - stepsOf(layout, 1)
      var total = 0.0
      var single = 0.0
      val (_, ms) = simulate(engine, scene, steps) { (step, built) =>
        if step > lastSecond then
          val lengths = built.jointLengths
          val errors = lengths.indices.map(i => math.abs(lengths(i) - rest(i)))
          total = math.max(total, errors.sum)
          single = math.max(single, errors.max)
      }
      Outcome(IndexedSeq(IndexedSeq(total), IndexedSeq(100 * single)), ms)

  /** ballpit-N after 15 s: balls whose centre left the container's inside (beyond a wall's
    * inner face or below the floor's top), the deepest ball into the floor, the fastest ball.
    */
  final case class Pit(balls: Int) extends Trial:
    private val scene = Ballpit(balls)
    val name: String = scene.name
    val measures: Seq[Measure] = Seq(
      Measure("balls outside the container after 15 s", "0", atMost(0), count),
      Measure("deepest ball into the floor after 15 s, m", "<= 0.02", atMost(0.02), fixed(4)),
      Measure("fastest ball after 15 s, m/s", "< 1", below(1), fixed(3)))
    def run(engine: Engine): Outcome =
      val layout = scene.layout
      val inside = layout.bounds
      val radii = layout.freeBodies.map(i =>
        layout.bodies(i).outline match
          case Outline.Circle(radius) => radius
          case Outline.Box(_, halfHeight) => halfHeight)
      val (built, ms) = simulate(engine, scene, stepsOf(layout, 15))((_, _) => ())
      val states = built.dynamicStates
      val velocities = built.dynamicVelocities
      var outside = 0
      var deepest = 0.0
      var fastest = 0.0
      for i <- radii.indices do
        val x = states(3 * i)
        val y = states(3 * i + 1)
        if x < inside.minX || x > inside.maxX || y < inside.minY then outside += 1
        deepest = math.max(deepest, radii(i) - y)
        fastest = math.max(fastest, math.hypot(velocities(3 * i), velocities(3 * i + 1)))
      Outcome(IndexedSeq(IndexedSeq(outside.toDouble), IndexedSeq(deepest), IndexedSeq(fastest)), ms)

  /** heavy-stack after 10 s: how far the heavy top box sank from its start, and its tilt. */
  object Heavy extends Trial:
    val name: String = HeavyStack.name
    val measures: Seq[Measure] = Seq(
      Measure("top box (100x denser) sink after 10 s, m", "< 0.03", below(0.03), fixed(4)),
      Measure("top box tilt after 10 s, rad (upright)", "<= 0.05", atMost(0.05), fixed(4)))
    def run(engine: Engine): Outcome =
      val initial = initialCentres(HeavyStack.layout)
      val top = initial.length - 1
      val (built, ms) = simulate(engine, HeavyStack, stepsOf(HeavyStack.layout, 10))((_, _) => ())
      val states = built.dynamicStates
      Outcome(IndexedSeq(IndexedSeq(initial(top).y - states(3 * top + 1)), IndexedSeq(tilt(states(3 * top + 2)))), ms)

  /** drop-eE over 5 s: the first three rebound heights (apexes of the ball's lowest point above
    * the ground's top face) as fractions of the 1 m drop; for E = 0.5 also the first against E^2.
    * A rebound is a flight upwards (the ball's vertical velocity above 0) whose top is at least
    * [[DropTrial.MinimumRise]] above the lowest point before it: a ball pushed out of the ground by
    * position correction, or wobbling at rest, is not bouncing. Missing rebounds are 0.
    */
  final case class DropTrial(restitution: Double) extends Trial:
    private val scene = Drop(restitution)
    val name: String = scene.name
    private val expected = restitution * restitution
    val measures: Seq[Measure] =
      Measure("rebound apexes 1 / 2 / 3 in 5 s, fractions of the drop", "each <= 1", atMost(1), fixed(3)) +:
        (if restitution == 0.5 then
           Seq(Measure(s"first rebound / e^2 (e^2 = $expected)", "1 ± 0.12", _.forall(v => math.abs(v - 1) <= 0.12), fixed(3)))
         else Nil)
    def run(engine: Engine): Outcome =
      val apexes = IndexedSeq.newBuilder[Double]
      var trough = Drop.Height // the lowest the ball has been since the last rebound's top
      var top = Double.NegativeInfinity // the highest in the flight upwards under way
      var rising = false
      val (_, ms) = simulate(engine, scene, stepsOf(scene.layout, 5)) { (_, built) =>
        val height = built.dynamicStates(1) - Drop.Radius
        if built.dynamicVelocities(1) > 0 then
          rising = true
          top = math.max(top, height)
        else
          if rising then // the flight upwards ended at this step or the one before
            top = math.max(top, height)
            if top - trough >= DropTrial.MinimumRise then
              apexes += top / Drop.Height
              trough = height
            rising = false
            top = Double.NegativeInfinity
          trough = math.min(trough, height)
      }
      val found = apexes.result().padTo(3, 0.0).take(3)
      val values = IndexedSeq(found) ++ (if restitution == 0.5 then IndexedSeq(IndexedSeq(found(0) / expected)) else Nil)
      Outcome(values, ms)

  object DropTrial:
    /** The least rise above the last low point that counts as a rebound, m (1% of the drop). */
    val MinimumRise: Double = 0.01

  /** The same scene twice from scratch gives the same bits (every free body's position,
    * rotation and velocities after 5 s); in SiMS also a snapshot taken halfway, restored after
    * the run and stepped again to the end.
    */
  object Determinism extends Trial:
    private val scene = Ballpit(500)
    private val Steps = 300
    val name: String = "determinism"
    val measures: Seq[Measure] = Seq(
      Measure(s"${scene.name} run twice for 5 s: the same final state", "yes", yes, yesNo),
      Measure("snapshot at 2.5 s, restore after 5 s, replay: the same final state", "yes", yes, yesNo))

    private def bits(values: Array[Double]): Seq[Long] = values.toSeq.map(java.lang.Double.doubleToRawLongBits)
    private def finalState(built: EngineScene): Seq[Long] = bits(built.dynamicStates ++ built.dynamicVelocities)
    private def worldState(world: World): Seq[Long] =
      bits(world.bodies.toArray.flatMap(b =>
          Array(b.pos.x, b.pos.y, b.rotation, b.linearVelocity.x, b.linearVelocity.y, b.angularVelocity)))
    private def flag(same: Boolean): Double = if same then 1 else 0

    def run(engine: Engine): Outcome =
      val (first, ms) = simulate(engine, scene, Steps)((_, _) => ())
      val (second, _) = simulate(engine, scene, Steps)((_, _) => ())
      val replay = engine.solver match
        case Some(solver) =>
          val world = SimsBuilder.world(scene, solver)
          for _ <- 1 to Steps / 2 do world.step()
          val halfway = world.snapshot()
          for _ <- 1 to Steps / 2 do world.step()
          val once = worldState(world)
          world.restore(halfway)
          for _ <- 1 to Steps / 2 do world.step()
          flag(worldState(world) == once)
        case None => Double.NaN
      Outcome(IndexedSeq(IndexedSeq(flag(finalState(first) == finalState(second))), IndexedSeq(replay)), ms)

  /** Every trial, in the order of the report. */
  val trials: Seq[Trial] =
    Seq(Pyramid, Stack, Chain, Pit(2000), Pit(4000), Heavy) ++ Drop.Restitutions.map(DropTrial(_)) :+ Determinism

  // ---- The report

  /** The table's lines of one trial: one per measure, then its time per step. */
  def lines(trial: Trial, outcomes: Seq[Outcome]): Seq[Line] =
    val soft = Engines.indexOf(Engine.SimsSoft)
    val measured = trial.measures.zipWithIndex.map { (measure, m) =>
      val cells = outcomes.map(_.values(m).map(measure.show).mkString(" / "))
      val meets = outcomes(soft).values(m)
      Line(trial.name, measure.name, measure.target, cells, Some(meets.nonEmpty && measure.meets(meets)))
    }
    val timed = Option.when(trial ne Determinism)(
      Line(trial.name, "ms per step in this run", "-", outcomes.map(o => fixed(3)(o.millisPerStep)), None))
    measured ++ timed

  /** The Markdown table of the lines. */
  def table(lines: Seq[Line]): String =
    val header = s"| scene | measure | SoftStep target | ${Engines.map(_.label).mkString(" | ")} | SoftStep meets it |\n" +
      s"|---|---|---|${Engines.map(_ => "---:").mkString("|")}|---|\n"
    header + lines.map { l =>
      val verdict = l.softMeets.map(if _ then "yes" else "**no**").getOrElse("")
      s"| ${l.trial} | ${l.measure} | ${l.target} | ${l.cells.mkString(" | ")} | $verdict |"
    }.mkString("", "\n", "\n")

  /** The whole report: settings, the table, and how each number is measured. */
  def report(lines: Seq[Line], date: String, minutes: Double): String =
    val runtime = Runtime.getRuntime
    val met = lines.flatMap(_.softMeets)
    s"""# Quality of the step: SiMS (classic and soft) vs jBox2D 2.2.1.1 vs dyn4j 5.0.2 ($date)
       |
       |Made by `./sbt "bench/runMain sims.bench.Quality"` in ${"%.1f".format(minutes)} min on ${runtime.availableProcessors} cores,
       |${System.getProperty("os.name")} ${System.getProperty("os.arch")}, Java ${System.getProperty("java.version")}.
       |Every engine with its defaults at 60 Hz and the bench's settings: SiMS with the classic step (10 iterations)
       |and with `SoftStep()` (its defaults: 4 substeps, contacts 30 Hz, joints 60 Hz, ...); jBox2D and dyn4j with
       |10 velocity and 10 position iterations, sleeping and continuous collision detection off. Friction 0.5 for
       |every pair, restitution 0 except in the drops (there the pair's value is e in every engine), density 1.
       |The soft step meets ${met.count(identity)} of the ${met.size} targets.
       |
       |""".stripMargin + table(lines) + s"""
       |How each number is measured (the same code for every engine, from each engine's own state):
       |
       |- pyramid-20 (210 boxes of 0.5 m in 20 rows): after 600 steps, the mean height of the boxes' centres
       |  as a percentage of the mean at the start; how far the top box's centre dropped; the fastest box's speed.
       |  jBox2D keeps 1 cm of skin around every polygon, so its boxes rest 2 cm apart and its pyramid ends up taller
       |  than it started.
       |- stack-12 (12 boxes of 0.5 m stacked straight up, shifted by up to 4 mm): after every step of 30 s, the
       |  top box's sideways distance from its start and every box's tilt (its angle's distance from 0 modulo a full
       |  turn); the largest of each.
       |- chain-100 (100 circles 0.2 m apart, distance joints, the first fixed): in each step of the last second of
       |  10 s, every link's |length - rest length|; the largest sum over the 99 links and the largest single one.
       |- ballpit-N: after 15 s, the balls whose centre is beyond a wall's inner face (|x| > 5) or below the floor's
       |  top (y < 0); the deepest a ball reaches into the floor (radius - centre height); the fastest ball.
       |- heavy-stack (3 boxes of 0.5 m, the top one 100 times denser): after 10 s, how far the top box's centre
       |  sank from its start, and its tilt.
       |- drop-eE (a ball of radius 0.25 m dropped from 1 m; both shapes get e, so the pair's value is e in every
       |  engine: the peers take the larger of two values, SiMS the product of their square roots): the ball's
       |  lowest point after each step; the top of each flight upwards (vertical velocity above 0) that rises at
       |  least 1 cm above the low point before it is a rebound apex, as a fraction of the 1 m drop (a ball pushed
       |  out of the ground by position correction has no upward velocity); missing rebounds are 0. jBox2D keeps
       |  1 cm of skin around polygons, so its ball turns 1 cm above the ground's face. A perfect bounce rises to e^2 of
       |  the drop, then e^4, ...
       |- determinism: ballpit-500 built twice and run 300 steps each; every free body's position, rotation and
       |  velocities compared bit for bit. In SiMS also: a snapshot at step 150, run to 300, restored, run to 300
       |  again: the same bits.
       |- ms per step: wall time of the steps alone in this run (SiMS's solvers, then the peers, one after the
       |  other, after a warm-up on the determinism trial); the JMH figures come from `RunAll`.
       |""".stripMargin

  def main(args: Array[String]): Unit =
    var out: Option[String] = None
    val names = Seq.newBuilder[String]
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--out" => out = Some(it.next())
        case name => names += name.toLowerCase
    val wanted = names.result()
    val unknown = wanted.filterNot(n => trials.exists(_.name == n))
    if unknown.nonEmpty then
      throw IllegalArgumentException(s"unknown trial ${unknown.mkString(", ")}; the trials: ${trials.map(_.name).mkString(" ")}")
    val chosen = if wanted.isEmpty then trials else trials.filter(t => wanted.contains(t.name))
    val started = System.nanoTime()
    // The determinism trial runs first: it also warms every engine's code up before the timed trials.
    val order = chosen.sortBy(t => if t eq Determinism then 0 else 1)
    val outcomes = order.map { trial =>
      trial -> Engines.map { engine =>
        val start = System.nanoTime()
        val outcome = trial.run(engine)
        println(f"${trial.name}%-14s ${engine.label}%-9s ${(System.nanoTime() - start) / 1e9}%6.1f s")
        outcome
      }
    }.toMap
    val minutes = (System.nanoTime() - started) / 6e10
    val all = chosen.flatMap(t => lines(t, outcomes(t)))
    val date = java.time.LocalDate.now().toString
    val text = report(all, date, minutes)
    // sbt forks the run in bench/; paths are taken relative to the repository's root.
    val root = if Files.isDirectory(Path.of("bench/results")) then Path.of(".") else Path.of("..")
    val file = root.resolve(out.getOrElse(s"bench/results/quality-$date.md"))
    Files.writeString(file, text)
    println()
    println(text)
    println(s"written to ${file.toAbsolutePath.normalize}")
