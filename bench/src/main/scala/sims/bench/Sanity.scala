package sims.bench

/** Checks that a scene still looks like what it should after a run, with the same criteria
  * for every engine, so that a fast wrong answer cannot win.
  */
object Sanity:
  /** Outcome of a check: whether it passed and what was measured. */
  final case class Result(ok: Boolean, detail: String)

  /** Slack allowed beyond a container's inner faces, m. */
  val ContainerTolerance: Double = 0.05
  /** A pyramid box may move this far (one box side) from its initial centre and still stand, m. */
  val PyramidDrift: Double = 0.5
  /** A standing pyramid box is turned by at most this much from a multiple of 90 degrees, rad. */
  val PyramidTilt: Double = 0.2
  /** A chain joint may differ from its length by this fraction: a quarter of a link. (Both
    * peers' rigid distance joints, at 10 iterations without sub-stepping, stretch by up to
    * about 20% while the chain swings.)
    */
  val ChainStretch: Double = 0.25

  /** Checks the named scene. */
  def check(scene: String, built: EngineScene): Result =
    val states = built.dynamicStates
    if states.exists(d => d.isNaN || d.isInfinite) then Result(false, "NaN or infinite body state")
    else scene match
      case "pyramid-20" => pyramid(states)
      case "chain-100" => chain(built.jointLengths)
      case "ballstack" =>
        inBox(states, Scenes.BallStack.Radius, Scenes.BallStack.HalfWidth, Scenes.BallStack.Height)
      case other =>
        val n = Scenes.ballpitSize(other).get
        inBox(states, Scenes.Ballpit.Radius, Scenes.Ballpit.HalfWidth, Scenes.Ballpit.wallHeight(n))

  /** Every ball within the walls (|x| <= halfWidth - r) and above the floor (y >= r). */
  private def inBox(states: Array[Double], radius: Double, halfWidth: Double, height: Double): Result =
    var outside = 0
    var lowest = Double.PositiveInfinity
    var widest = 0.0
    var i = 0
    while i < states.length do
      val x = states(i)
      val y = states(i + 1)
      lowest = math.min(lowest, y - radius)
      widest = math.max(widest, math.abs(x) + radius)
      if math.abs(x) + radius > halfWidth + ContainerTolerance || y - radius < -ContainerTolerance then outside += 1
      i += 3
    Result(outside == 0, f"$outside%d outside; lowest ball bottom $lowest%.3f m, widest |x|+r $widest%.3f m")

  /** Every box within [[PyramidDrift]] of where it started and turned by at most [[PyramidTilt]]. */
  private def pyramid(states: Array[Double]): Result =
    val initial = Scenes.Pyramid.centres
    var drift = 0.0
    var tilt = 0.0
    var i = 0
    while i < initial.length / 2 do
      drift = math.max(drift, math.hypot(states(3 * i) - initial(2 * i), states(3 * i + 1) - initial(2 * i + 1)))
      tilt = math.max(tilt, math.abs(math.IEEEremainder(states(3 * i + 2), math.Pi / 2)))
      i += 1
    Result(drift <= PyramidDrift && tilt <= PyramidTilt, f"largest drift $drift%.3f m, largest tilt $tilt%.3f rad")

  /** Every joint within [[ChainStretch]] of its length. */
  private def chain(lengths: Array[Double]): Result =
    val worst = lengths.map(l => math.abs(l - Scenes.Chain.Spacing)).max
    val total = lengths.sum
    Result(worst <= ChainStretch * Scenes.Chain.Spacing,
      f"largest joint error ${worst * 1000}%.1f mm, chain length $total%.2f m (rest ${Scenes.Chain.Spacing * lengths.length}%.2f m)")
