package sims.sweep.examples

import java.nio.file.{Files, Path}
import javax.imageio.ImageIO
import sims.sweep.{Axis, Backend, Grid, LocalBackend, ResultTable}
import sims.sweep.spark.SparkBackend

/** Command line of the Cannon sweep:
  * `[--backend local|spark] [--threads N] [--master M] [--runs small|full] [--out DIR]`. Writes
  * `cannon-sweep.csv`, `.parquet` and `.png` into the output directory.
  */
object Main:
  /** Parsed command line.
    *
    * @param threads the local back end's threads (all processors unless given)
    * @param master the Spark back end's master (spark-submit's, when it sets one)
    * @param small 40 runs (a coarse grid) instead of 2,000
    */
  final case class Options(spark: Boolean = false, threads: Int = Runtime.getRuntime.availableProcessors,
      master: String = "local[*]", small: Boolean = false, out: Path = Path.of("out"))

  /** Usage text. */
  val Usage: String =
    """usage: sweep/run [--backend local|spark] [--threads N] [--master M] [--runs full|small] [--out DIR]
      |  the Cannon scene over muzzle speed x restitution x friction (2,000 runs; small: 40),
      |  on this machine's cores (local, the default: --threads, all unless given) or on Spark
      |  (--master, local[*] unless given or set by spark-submit); writes cannon-sweep.csv,
      |  cannon-sweep.parquet and cannon-sweep.png into DIR (out unless given)""".stripMargin

  /** Parses the arguments; Left holds an error message. */
  def parse(arguments: Seq[String]): Either[String, Options] =
    def loop(rest: List[String], options: Options): Either[String, Options] = rest match
      case Nil => Right(options)
      case "--backend" :: "local" :: tail => loop(tail, options.copy(spark = false))
      case "--backend" :: "spark" :: tail => loop(tail, options.copy(spark = true))
      case "--backend" :: value :: _ => Left(s"--backend is local or spark, got '$value'")
      case "--threads" :: value :: tail =>
        value.toIntOption.filter(_ >= 1) match
          case Some(threads) => loop(tail, options.copy(threads = threads))
          case None => Left(s"--threads needs a whole number at least 1, got '$value'")
      case "--master" :: value :: tail => loop(tail, options.copy(master = value))
      case "--runs" :: "full" :: tail => loop(tail, options.copy(small = false))
      case "--runs" :: "small" :: tail => loop(tail, options.copy(small = true))
      case "--runs" :: value :: _ => Left(s"--runs is full or small, got '$value'")
      case "--out" :: value :: tail => loop(tail, options.copy(out = Path.of(value)))
      case flag :: Nil if Set("--backend", "--threads", "--master", "--runs", "--out")(flag) => Left(s"$flag needs a value")
      case other :: _ => Left(s"unknown argument $other")
    loop(arguments.toList, Options())

  /** The coarse grid of `--runs small`: 5 speeds x 4 restitutions x 2 frictions. */
  val SmallGrid: Grid = Grid(Axis.stepped("speed", 5, 23, 4.5), Axis.evenly("restitution", 0, 0.9, 4),
    Axis.evenly("friction", 0.3, 0.9, 2))

  /** Runs the sweep and writes its files. */
  def main(arguments: Array[String]): Unit =
    parse(arguments.toSeq) match
      case Left(error) =>
        System.err.println(error)
        System.err.println(Usage)
        sys.exit(2)
      case Right(options) =>
        val sweep = CannonSweep.sweep(if options.small then SmallGrid else CannonSweep.parameters)
        def timed(backend: Backend): ResultTable =
          println(s"${sweep.parameters.size} runs of ${CannonSweep.Steps} steps on $backend ...")
          val start = System.nanoTime
          val table = sweep.run(backend)
          val seconds = (System.nanoTime - start) / 1e9
          println(f"done in $seconds%.1f s: ${table.size / seconds}%.0f runs per second")
          table
        val table =
          if options.spark then SparkBackend.using(options.master, "sims-sweep-cannon")(timed)
          else timed(LocalBackend(options.threads))
        Files.createDirectories(options.out)
        table.writeCsv(options.out.resolve("cannon-sweep.csv"))
        table.writeParquet(options.out.resolve("cannon-sweep.parquet"))
        System.setProperty("java.awt.headless", "true")
        val picture = Heatmaps.draw(table, "speed", "restitution", "friction", "fallen",
          s"Cannon: boxes of the pyramid fallen after ${CannonSweep.Steps / 60} s, by muzzle speed (m/s), restitution and friction")
        ImageIO.write(picture, "png", options.out.resolve("cannon-sweep.png").toFile)
        val fallen = table("fallen")
        println(f"fallen: ${fallen.min}%.0f to ${fallen.max}%.0f of 36 boxes, ${fallen.sum / fallen.size}%.1f on average")
        println(s"wrote ${options.out.resolve("cannon-sweep")}.csv, .parquet and .png")
