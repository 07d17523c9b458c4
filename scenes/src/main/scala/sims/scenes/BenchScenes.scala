package sims.scenes

/** The benchmark scenes: `ballpit-N`, `pyramid-R` and `chain-N` for any size, laid out as
  * [[Layout]]s that every engine of the bench builds, and `ballstack` (SiMS only), the
  * examples' [[BallStack]]; and the quality report's layouts: `stack-N`, `heavy-stack` and
  * `drop-eE` (restitution E from 0 to 1).
  */
object BenchScenes:
  /** The ball pits benchmarked. */
  val BallpitSizes: Seq[Int] = Seq(500, 1000, 2000, 4000, 8000, 16000)

  /** The scenes benchmarked, in the order of the bench's reports. */
  val standard: Seq[Scene] = BallpitSizes.map(Ballpit(_)) ++ Seq(BoxPyramid(20), SwingingChain(100), BallStack)

  /** The bench's names of the standard scenes: their names in lower case. */
  val names: Seq[String] = standard.map(_.name.toLowerCase)

  /** The scenes of the quality report (`sims.bench.Quality`), in its order. */
  val quality: Seq[LayoutScene] = Seq(BoxPyramid(20), BoxStack(12), SwingingChain(100), Ballpit(2000), Ballpit(4000),
    HeavyStack) ++ Drop.Restitutions.map(Drop(_))

  private val Family = "(ballpit|pyramid|chain|stack)-([0-9]{1,6})".r
  private val DropFamily = "drop-e([0-9]+(?:\\.[0-9]+)?)".r

  /** The benchmark scene with this name, ignoring case: `ballpit-N`, `pyramid-R`, `chain-N`,
    * `stack-N` for any size they accept, `drop-eE` for E from 0 to 1 (`drop-e0.5`),
    * `heavy-stack` or `ballstack`.
    */
  def find(name: String): Option[Scene] = name.toLowerCase match
    case Family("ballpit", n) if n.toInt > 0 => Some(Ballpit(n.toInt))
    case Family("pyramid", n) if n.toInt > 0 => Some(BoxPyramid(n.toInt))
    case Family("chain", n) if n.toInt > 1 => Some(SwingingChain(n.toInt))
    case Family("stack", n) if n.toInt > 0 => Some(BoxStack(n.toInt))
    case DropFamily(e) if e.toDouble <= 1 => Some(Drop(e.toDouble))
    case "heavy-stack" => Some(HeavyStack)
    case "ballstack" => Some(BallStack)
    case _ => None
