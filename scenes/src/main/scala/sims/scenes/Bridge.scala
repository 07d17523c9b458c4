package sims.scenes

import sims.dynamics.{Body, Rectangle, World}
import sims.dynamics.joints.RevoluteJoint
import sims.geometry.{PortableMath, Vector2D}
import sims.solver.SoftStep

/** A plank bridge between two fixed piers: planks pinned end to end by revolute joints that
  * break above `BreakForce`, the end planks pinned to the piers. It hangs a little slack and
  * holds its own weight; after a second a heavy load is dropped onto its middle from just above,
  * the joints' pull grows past their limit, some break (the step reports them in
  * `World.jointBreaks` and removes them), and the load falls through onto the river bed. Soft
  * step only: the classic step measures no joint's load, so no joint of it breaks.
  */
object Bridge extends Scene:
  /** Planks, their half length and half thickness, m, and density, kg/m^2. */
  val Planks: Int = 9
  val PlankHalfLength: Double = 0.5
  val PlankHalfThickness: Double = 0.1
  val PlankDensity: Double = 1
  /** The deck's top face, m (the piers' tops too). */
  val DeckTop: Double = 3
  /** The joints' break force, N. */
  val BreakForce: Double = 800
  /** The load's half side, m, its density, kg/m^2, and how high above the deck's top its middle
    * starts, m, at the end of step `DropStep` (one second).
    */
  val LoadHalf: Double = 0.4
  val LoadDensity: Double = 60
  val DropHeight: Double = 1
  val DropStep: Int = 60
  /** Half the distance between the piers' inner faces, m: a little less than the planks' half
    * length in all, so that the deck hangs with some slack.
    */
  val HalfGap: Double = 4.45

  /** Each plank's slope, rad, left to right, as the bridge is built: a slope growing evenly from
    * -a to a along the deck (a hanging deck's shape), a chosen so that the planks span the gap.
    */
  val Slopes: IndexedSeq[Double] =
    val steps = (0 until Planks).map(i => (2.0 * i - (Planks - 1)) / (Planks - 1))
    def span(a: Double): Double = steps.map(t => 2 * PlankHalfLength * PortableMath.cos(a * t)).sum
    // The span shrinks as a grows (from the planks' whole length at a = 0): halve the interval.
    var low = 0.0
    var high = math.Pi / 2
    for _ <- 1 to 60 do
      val middle = (low + high) / 2
      if span(middle) > 2 * HalfGap then low = middle else high = middle
    steps.map(_ * low)

  /** The pins' points as the bridge is built, left to right, m: on the piers' inner faces at the
    * ends, the planks' ends between.
    */
  val Pins: IndexedSeq[Vector2D] =
    Slopes.scanLeft(Vector2D(-HalfGap, DeckTop - PlankHalfThickness)) { (pin, slope) =>
      pin + Vector2D(PortableMath.cos(slope), PortableMath.sin(slope)) * (2 * PlankHalfLength)
    }

  def name: String = "Bridge"
  def description: String =
    "A plank bridge on breakable revolute joints holds its own weight; a heavy load dropped on it breaks it and falls through."
  def view: Region = Region(-9, -0.5, 9, 8)
  override def softStepOnly: Boolean = true

  /** The bridge's planks and joints in the world they were added to. */
  final case class Parts(planks: Seq[Body], joints: Seq[RevoluteJoint])

  /** A world that drops the load onto the bridge at the end of step `DropStep` (or never, without
    * the load).
    */
  final class BridgeWorld(withLoad: Boolean) extends World:
    solver = SoftStep()
    /** The load, once dropped. */
    var load: Option[Body] = None
    private var steps = 0

    override def postStep(): Unit =
      steps += 1
      if steps == DropStep && withLoad then
        val box = Rectangle(LoadHalf, LoadHalf, LoadDensity)
        box.pos = Vector2D(0, DeckTop + DropHeight)
        box.restitution = 0
        val body = box.asBody
        this += body
        load = Some(body)

  /** The scene's world and its bridge; without the load if `withLoad` is false (the bridge
    * alone, to see what it holds of its own weight).
    */
  def stage(withLoad: Boolean = true): (Staged, Parts) =
    val world = BridgeWorld(withLoad)
    world += Scene.ground(9)
    val piers =
      for side <- Seq(-1.0, 1.0) yield
        val pier = Scene.fixedBox(Vector2D(side * (HalfGap + 1), DeckTop / 2), 1, DeckTop / 2)
        world += pier
        pier
    val planks =
      for i <- 0 until Planks yield
        val plank = Rectangle(PlankHalfLength, PlankHalfThickness, PlankDensity)
        plank.pos = (Pins(i) + Pins(i + 1)) / 2
        plank.rotation = Slopes(i)
        plank.restitution = 0
        val body = plank.asBody
        world += body
        body
    // The pins, left to right: pier and first plank, plank and plank, last plank and pier.
    val chain = piers.head +: planks :+ piers.last
    val joints =
      for i <- 0 to Planks yield
        val joint = RevoluteJoint(chain(i), chain(i + 1), Pins(i))
        joint.collideConnected = false // neighbours meet end to end at the pin
        joint.breakForce = BreakForce
        world += joint
        joint
    (Staged(world), Parts(planks, joints))

  def build(): Staged = stage()._1
