package sims.scenes

import sims.dynamics.{Body, ChainSegment, Circle, Rectangle}
import sims.dynamics.joints.{JointLimits, JointMotor, JointSpring, WheelJoint}
import sims.geometry.{PortableMath, Vector2D}

/** A car drives over hills: a chassis on two wheels, each on a wheel joint whose suspension
  * (a spring along the chassis' vertical axis, within limits) carries it, the rear wheel turned
  * by a motor, over a terrain that is one chain of straight segments (smooth at its joins under
  * the soft step) between two walls. Soft step only: the classic step has no spring, motor nor
  * limits of a wheel joint.
  */
object Car extends Scene:
  /** Where the terrain's chain begins and ends, m (a wall stands at each end). */
  val TerrainStart: Double = -10
  val TerrainEnd: Double = 38
  /** The terrain's segments are this long horizontally, m. */
  val SegmentLength: Double = 1
  /** The hills' height and length, m: they begin at x = `HillsStart`, flat ground before. */
  val HillHeight: Double = 0.9
  val HillLength: Double = 8
  val HillsStart: Double = -2
  /** The walls' height above the ground at the chain's ends, m. */
  val WallHeight: Double = 2.5
  /** The chassis' half extents, m, and density, kg/m^2. */
  val ChassisHalfWidth: Double = 1.0
  val ChassisHalfHeight: Double = 0.2
  val ChassisDensity: Double = 4
  /** The wheels' radius, m, density, kg/m^2, and their axles' offset from the chassis' middle, m. */
  val WheelRadius: Double = 0.35
  val WheelDensity: Double = 2
  val AxleOffset: Vector2D = Vector2D(0.7, -0.3)
  /** Where the chassis' middle starts, m. */
  val Start: Vector2D = Vector2D(-6, WheelRadius - AxleOffset.y)
  /** The suspension: its spring and how far a wheel may travel along the axis from rest, m. */
  val Suspension: JointSpring = JointSpring(hertz = 4, dampingRatio = 0.7)
  val Travel: JointLimits = JointLimits(-0.2, 0.2)
  /** The rear wheel's motor: clockwise (forwards, to the right), rad/s, and its torque, N m. */
  val Motor: JointMotor = JointMotor(speed = -10, maxForce = 10)

  def name: String = "Car"
  def description: String =
    "A car on two sprung wheel joints, its rear wheel driven by a motor, drives over hills of a chain terrain."
  def view: Region = Region(TerrainStart - 1, -3, TerrainEnd + 1, 9)
  override def region: Region = Region(TerrainStart, -1, TerrainEnd, 8)
  override def softStepOnly: Boolean = true

  /** The terrain's height at x, m: flat, then hills of `HillHeight` every `HillLength`. */
  def height(x: Double): Double =
    if x <= HillsStart then 0
    else HillHeight / 2 * (1 - PortableMath.cos(2 * math.Pi * (x - HillsStart) / HillLength))

  /** The terrain's polyline, left to right (so its solid side is below), with a wall up at each end. */
  def terrainPoints: Seq[Vector2D] =
    val segments = math.round((TerrainEnd - TerrainStart) / SegmentLength).toInt
    val ground = (0 to segments).map { i =>
      val x = TerrainStart + i * SegmentLength
      Vector2D(x, height(x))
    }
    Vector2D(TerrainStart, WallHeight) +: ground :+ Vector2D(TerrainEnd, height(TerrainEnd) + WallHeight)

  /** The car's parts in the world they were added to. */
  final case class Parts(chassis: Body, rear: Body, front: Body, rearAxle: WheelJoint, frontAxle: WheelJoint):
    /** Both axles, rear first. */
    def axles: Seq[WheelJoint] = Seq(rearAxle, frontAxle)

  /** The scene's world and its car. */
  def stage(): (Staged, Parts) =
    val world = Scene.softWorldOf()
    val terrain = Body(ChainSegment.chain(terrainPoints)*)
    terrain.fixed = true
    world += terrain
    val body = Rectangle(ChassisHalfWidth, ChassisHalfHeight, ChassisDensity)
    body.pos = Start
    body.restitution = 0
    val chassis = body.asBody
    world += chassis
    val wheels =
      for side <- Seq(-1.0, 1.0) yield
        val circle = Circle(WheelRadius, WheelDensity)
        circle.pos = Start + Vector2D(side * AxleOffset.x, AxleOffset.y)
        circle.friction = 1
        circle.restitution = 0
        val wheel = circle.asBody
        world += wheel
        val axle = WheelJoint(chassis, wheel, wheel.pos, Vector2D(0, 1))
        axle.spring = Some(Suspension)
        axle.limits = Some(Travel)
        axle.collideConnected = false // the wheel turns inside the chassis' outline
        world += axle
        (wheel, axle)
    val (rear, rearAxle) = wheels.head
    val (front, frontAxle) = wheels.last
    rearAxle.motor = Some(Motor)
    (Staged(world), Parts(chassis, rear, front, rearAxle, frontAxle))

  def build(): Staged = stage()._1
