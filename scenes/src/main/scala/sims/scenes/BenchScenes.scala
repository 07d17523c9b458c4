package sims.scenes

/** The benchmark scenes: `ballpit-N`, `pyramid-R` and `chain-N` for any size, laid out as
  * [[Layout]]s that every engine of the bench builds, and `ballstack` (SiMS only), the
  * examples' [[BallStack]]; Box2D v3's own benchmark scenes `large_pyramid`, `many_pyramids`,
  * `joint_grid` and `smash` (layouts too, at the benchmark's sizes or smaller) and `rain`
  * (SiMS's soft step only: ragdolls with motors and springs, [[Rain]]); and the
  * quality report's layouts: `stack-N`, `heavy-stack` and `drop-eE` (restitution E from 0 to 1).
  */
object BenchScenes:
  /** The ball pits benchmarked. */
  val BallpitSizes: Seq[Int] = Seq(500, 1000, 2000, 4000, 8000, 16000)

  /** The scenes benchmarked, in the order of the bench's reports. */
  val standard: Seq[Scene] = BallpitSizes.map(Ballpit(_)) ++ Seq(BoxPyramid(20), SwingingChain(100), BallStack) ++
    Seq(LargePyramid(), ManyPyramids(), JointGrid(), Smash(), Rain())

  /** The bench's names of the standard scenes: their names in lower case. */
  val names: Seq[String] = standard.map(_.name.toLowerCase)

  /** The scenes of the quality report (`sims.bench.Quality`), in its order. */
  val quality: Seq[LayoutScene] = Seq(BoxPyramid(20), BoxStack(12), SwingingChain(100), Ballpit(2000), Ballpit(4000),
    HeavyStack) ++ Drop.Restitutions.map(Drop(_))

  private val Family = "(ballpit|pyramid|chain|stack)-([0-9]{1,6})".r
  private val DropFamily = "drop-e([0-9]+(?:\\.[0-9]+)?)".r
  private val Box2DFamily = "(large_pyramid|joint_grid)-([0-9]{1,4})".r
  private val GridFamily = "(many_pyramids|smash)-([0-9]{1,4})x([0-9]{1,4})".r
  private val RainFamily = "rain-([0-9]{1,2})x([0-9]{1,3})x([0-9]{1,2})".r

  /** The benchmark scene with this name, ignoring case: `ballpit-N`, `pyramid-R`, `chain-N`,
    * `stack-N` for any size they accept, `drop-eE` for E from 0 to 1 (`drop-e0.5`),
    * `heavy-stack` or `ballstack`; Box2D's `large_pyramid`, `many_pyramids`, `joint_grid` and
    * `smash`, or smaller ones: `large_pyramid-B` (B boxes in the bottom row), `joint_grid-S`
    * (S x S discs), `many_pyramids-RxC` (R rows of C pyramids), `smash-CxR` (a wall of C
    * columns and R rows); `rain`, or `rain-RxCxG` (R floors, C columns of groups of G).
    */
  def find(name: String): Option[Scene] = name.toLowerCase match
    case Family("ballpit", n) if n.toInt > 0 => Some(Ballpit(n.toInt))
    case Family("pyramid", n) if n.toInt > 0 => Some(BoxPyramid(n.toInt))
    case Family("chain", n) if n.toInt > 1 => Some(SwingingChain(n.toInt))
    case Family("stack", n) if n.toInt > 0 => Some(BoxStack(n.toInt))
    case DropFamily(e) if e.toDouble <= 1 => Some(Drop(e.toDouble))
    case "large_pyramid" => Some(LargePyramid())
    case "many_pyramids" => Some(ManyPyramids())
    case "joint_grid" => Some(JointGrid())
    case "smash" => Some(Smash())
    case "rain" => Some(Rain())
    case Box2DFamily("large_pyramid", n) if n.toInt > 0 => Some(LargePyramid(n.toInt))
    case Box2DFamily("joint_grid", n) if n.toInt >= 7 => Some(JointGrid(n.toInt))
    case GridFamily("many_pyramids", r, c) if r.toInt > 0 && c.toInt > 0 => Some(ManyPyramids(r.toInt, c.toInt))
    case GridFamily("smash", c, r) if c.toInt > 0 && r.toInt > 0 => Some(Smash(c.toInt, r.toInt))
    case RainFamily(r, c, g) if r.toInt > 0 && c.toInt > 0 && g.toInt > 0 => Some(Rain(r.toInt, c.toInt, g.toInt))
    case "heavy-stack" => Some(HeavyStack)
    case "ballstack" => Some(BallStack)
    case _ => None
