package sims.bench

import sims.scenes.{
  BallStack, Ballpit, BoxPyramid, BoxStack, HeavyStack, JointGrid, LargePyramid, Layout, ManyPyramids, Outline, Region, Scene, Smash,
  SwingingChain
}

/** Checks that a scene still looks like what it should after a run, with the same criteria
  * for every engine, so that a fast wrong answer cannot win. Containers, initial positions and
  * joint lengths come from the scene itself.
  */
object Sanity:
  /** Outcome of a check: whether it passed and what was measured. */
  final case class Result(ok: Boolean, detail: String)

  /** Slack allowed beyond a container's inner faces, m. */
  val ContainerTolerance: Double = 0.05
  /** A pyramid or stack box may move this far (one box side) from its initial centre and still stand, m. */
  val PyramidDrift: Double = 0.5
  /** A standing pyramid or stack box is turned by at most this much from a multiple of 90 degrees, rad. */
  val PyramidTilt: Double = 0.2
  /** A chain joint may differ from its length by this fraction: a quarter of a link. (Both
    * peers' rigid distance joints, at 10 iterations without sub-stepping, stretch by up to
    * about 20% while the chain swings.)
    */
  val ChainStretch: Double = 0.25
  /** A joint grid's pin may open by this much: a quarter of the grid's 1 m pitch, m. */
  val PinGap: Double = 0.25
  /** Without gravity or fixed bodies a scene's momentum stays what it was; this fraction of it
    * may be lost or gained (single precision in jBox2D, the solvers' tolerances).
    */
  val MomentumTolerance: Double = 0.01

  /** Checks the scene; a scene without criteria of its own is only checked for NaN. */
  def check(scene: Scene, built: EngineScene): Result =
    val states = built.dynamicStates
    if states.exists(d => d.isNaN || d.isInfinite) then Result(false, "NaN or infinite body state")
    else
      scene match
        case pyramid: BoxPyramid => standing(states, pyramid.layout)
        case stack: BoxStack => standing(states, stack.layout)
        case HeavyStack => standing(states, HeavyStack.layout)
        case chain: SwingingChain => joined(built.jointLengths, chain.layout)
        case pyramid: LargePyramid => standing(states, pyramid.layout)
        case pyramids: ManyPyramids => standing(states, pyramids.layout)
        case grid: JointGrid => pinned(built.pinGaps)
        case smash: Smash => momentumKept(built.dynamicVelocities, smash.layout)
        case pit: Ballpit =>
          val radii = pit.layout.freeBodies.map(i =>
            pit.layout.bodies(i).outline match
              case Outline.Circle(radius) => radius
              case Outline.Box(halfWidth, halfHeight) => math.hypot(halfWidth, halfHeight))
          contained(states, radii, pit.layout.bounds)
        case BallStack => contained(states, IndexedSeq.fill(states.length / 3)(BallStack.Radius), BallStack.Inside)
        case _ => Result(true, "finite")

  /** Every ball within the walls and above the floor of `inside` (its top is not checked). */
  private def contained(states: Array[Double], radii: IndexedSeq[Double], inside: Region): Result =
    var outside = 0
    var lowest = Double.PositiveInfinity
    var widest = 0.0
    var i = 0
    while i < states.length / 3 do
      val x = states(3 * i)
      val y = states(3 * i + 1)
      val radius = radii(i)
      lowest = math.min(lowest, y - radius)
      widest = math.max(widest, math.abs(x) + radius)
      if x - radius < inside.minX - ContainerTolerance || x + radius > inside.maxX + ContainerTolerance ||
        y - radius < inside.minY - ContainerTolerance
      then outside += 1
      i += 1
    Result(outside == 0, f"$outside%d outside; lowest ball bottom $lowest%.3f m, widest |x|+r $widest%.3f m")

  /** Every box within [[PyramidDrift]] of where it started and turned by at most [[PyramidTilt]]. */
  private def standing(states: Array[Double], layout: Layout): Result =
    val initial = layout.freeBodies.map(layout.bodies(_).centre)
    var drift = 0.0
    var tilt = 0.0
    var i = 0
    while i < initial.length do
      drift = math.max(drift, math.hypot(states(3 * i) - initial(i).x, states(3 * i + 1) - initial(i).y))
      tilt = math.max(tilt, math.abs(math.IEEEremainder(states(3 * i + 2), math.Pi / 2)))
      i += 1
    Result(drift <= PyramidDrift && tilt <= PyramidTilt, f"largest drift $drift%.3f m, largest tilt $tilt%.3f rad")

  /** Every joint within [[ChainStretch]] of its length. */
  private def joined(lengths: Array[Double], layout: Layout): Result =
    val rest = layout.joints.map(layout.length)
    val worst = lengths.indices.map(i => math.abs(lengths(i) - rest(i)) / rest(i)).max
    val largest = lengths.indices.map(i => math.abs(lengths(i) - rest(i))).max
    Result(worst <= ChainStretch,
      f"largest joint error ${largest * 1000}%.1f mm, chain length ${lengths.sum}%.2f m (rest ${rest.sum}%.2f m)")

  /** Every pin of a joint grid open by at most [[PinGap]]. */
  private def pinned(gaps: Array[Double]): Result =
    val largest = if gaps.isEmpty then 0.0 else gaps.max
    val mean = if gaps.isEmpty then 0.0 else gaps.sum / gaps.length
    Result(largest <= PinGap, f"largest pin gap ${largest * 1000}%.1f mm, mean ${mean * 1000}%.2f mm")

  /** The free bodies' momentum within [[MomentumTolerance]] of the start's (a scene without
    * gravity or fixed bodies).
    */
  private def momentumKept(velocities: Array[Double], layout: Layout): Result =
    val free = layout.freeBodies
    val masses = free.map { i =>
      val body = layout.bodies(i)
      body.density *
        (body.outline match
          case Outline.Circle(radius) => math.Pi * radius * radius
          case Outline.Box(halfWidth, halfHeight) => 4 * halfWidth * halfHeight)
    }
    val startX = free.indices.map(k => masses(k) * layout.bodies(free(k)).velocity.x).sum
    val startY = free.indices.map(k => masses(k) * layout.bodies(free(k)).velocity.y).sum
    val nowX = free.indices.map(k => masses(k) * velocities(3 * k)).sum
    val nowY = free.indices.map(k => masses(k) * velocities(3 * k + 1)).sum
    val error = math.hypot(nowX - startX, nowY - startY) / math.hypot(startX, startY)
    Result(
      error <= MomentumTolerance, f"momentum ($nowX%.1f, $nowY%.1f) kg m/s, start ($startX%.1f, $startY%.1f): off by ${error * 100}%.2f%%")
