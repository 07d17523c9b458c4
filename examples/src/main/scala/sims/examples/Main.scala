package sims.examples

import java.io.File
import sims.examples.headless.HeadlessRun
import sims.scenes.{Scene, Scenes}

/** Command line of the examples: `[Scene] [--seconds S] [--out DIR] [--solver classic|soft]`
  * runs a scene headless, `--compare` runs it under both solvers side by side, `--gui [Scene]`
  * opens the viewer, `--list` lists the scenes.
  */
object Main:
  /** Simulated seconds of a headless run unless `--seconds` says otherwise. */
  val DefaultSeconds = 5.0
  /** Output directory unless `--out` says otherwise. */
  val DefaultOut = "out"

  /** Parsed command line.
    *
    * @param solver the solver of a headless run or the viewer's first one (None: the classic
    *   step, or the soft step for a scene that runs under it only)
    * @param compare run headless under both solvers, side by side in one picture
    */
  final case class Options(scene: Option[String] = None, seconds: Double = DefaultSeconds,
      out: File = File(DefaultOut), gui: Boolean = false, list: Boolean = false, help: Boolean = false,
      solver: Option[SolverChoice] = None, compare: Boolean = false)

  /** Usage text. */
  val Usage: String =
    s"""usage: examples/run [Scene] [--seconds S] [--out DIR] [--solver classic|soft]
      |                                        simulate headless, write GIF, PNG and CSV
      |       examples/run [Scene] --compare [--seconds S] [--out DIR]
      |                                        both solvers side by side: <scene>-compare.gif and .png
      |       examples/run --gui [Scene] [--solver classic|soft]
      |                                        open the interactive viewer
      |       examples/run --list              list the scenes
      |The solver is SiMS's own step (classic, the default) or the soft step (soft); a scene that
      |runs under the soft step only (${Scenes.all.filter(_.softStepOnly).map(_.name).mkString(", ")}) gets the soft step.""".stripMargin

  /** Parses the arguments; Left holds an error message. */
  def parse(arguments: Seq[String]): Either[String, Options] =
    def loop(rest: List[String], options: Options): Either[String, Options] = rest match
      case Nil =>
        if options.compare && options.gui then Left("--compare writes files: it cannot open the viewer (--gui)")
        else Right(options)
      case "--gui" :: tail => loop(tail, options.copy(gui = true))
      case "--compare" :: tail =>
        if arguments.contains("--solver") then Left("--compare runs both solvers: leave out --solver")
        else loop(tail, options.copy(compare = true))
      case "--solver" :: value :: tail =>
        SolverChoice.named(value) match
          case Some(choice) => loop(tail, options.copy(solver = Some(choice)))
          case None => Left(s"--solver is ${SolverChoice.values.map(_.argument).mkString(" or ")}, got '$value'")
      case "--list" :: tail => loop(tail, options.copy(list = true))
      case ("--help" | "-h") :: tail => loop(tail, options.copy(help = true))
      case "--seconds" :: value :: tail =>
        value.toDoubleOption.filter(s => s >= 0 && !s.isInfinite) match
          case Some(seconds) => loop(tail, options.copy(seconds = seconds))
          case None => Left(s"--seconds needs a number of seconds at least 0, got '$value'")
      case "--out" :: value :: tail => loop(tail, options.copy(out = File(value)))
      case ("--seconds" | "--out" | "--solver") :: Nil => Left(s"${rest.head} needs a value")
      case flag :: _ if flag.startsWith("--") => Left(s"unknown option $flag")
      case name :: tail =>
        if options.scene.isDefined then Left(s"only one scene may be named, got ${options.scene.get} and $name")
        else loop(tail, options.copy(scene = Some(name)))
    loop(arguments.toList, Options())

  /** The solver that runs `scene` as the options ask, or why it cannot: a scene that runs under
    * the soft step only refuses `--solver classic` and `--compare`.
    */
  def solverFor(scene: Scene, options: Options): Either[String, SolverChoice] =
    if scene.softStepOnly && options.compare then
      Left(s"${scene.name} runs under the soft step only: --compare needs a scene that runs under both solvers")
    else if scene.softStepOnly && options.solver.contains(SolverChoice.Classic) then
      Left(s"${scene.name} runs under the soft step only (ClassicStep cannot step its joints): leave out --solver or say --solver soft")
    else Right(SolverChoice.forScene(scene, options.solver.getOrElse(SolverChoice.Classic)))

  /** The listing of all scenes, one per line. */
  def listing: String =
    val width = Scenes.all.map(_.name.length).max
    Scenes.all.map(s => s"  ${s.name.padTo(width, ' ')}  ${s.description}${if s.softStepOnly then " (soft step only)" else ""}")
      .mkString("\n")

  /** Runs the command line. */
  def main(arguments: Array[String]): Unit =
    parse(arguments.toSeq) match
      case Left(error) =>
        System.err.println(error)
        System.err.println(Usage)
        sys.exit(2)
      case Right(options) if options.help =>
        println(Usage)
      case Right(options) if options.list =>
        println(listing)
      case Right(options) =>
        val scene: Scene = options.scene match
          case None => Scenes.default
          case Some(name) =>
            Scenes.find(name).getOrElse {
              System.err.println(s"no scene named '$name'; the scenes are:\n$listing")
              sys.exit(2)
            }
        val solver = solverFor(scene, options) match
          case Right(choice) => choice
          case Left(error) =>
            System.err.println(error)
            sys.exit(2)
        if options.gui then
          if java.awt.GraphicsEnvironment.isHeadless then
            System.err.println("the viewer needs a display; without one, run a scene headless: examples/run " + scene.name)
            sys.exit(1)
          viewer.Viewer.open(scene, solver)
        else
          // No window is ever opened here: headless mode also works on machines without a display.
          System.setProperty("java.awt.headless", "true")
          if options.scene.isEmpty then
            println(s"Scenes:\n$listing\n\nNo scene named, running ${scene.name} (see --help).\n")
          if options.compare then HeadlessRun.compare(scene, options.seconds, options.out)
          else HeadlessRun.run(scene, options.seconds, options.out, solver = solver)
