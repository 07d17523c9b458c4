package sims.scenes

import sims.dynamics.{Body, Rectangle, Shape, World}
import sims.dynamics.joints.{JointMotor, RevoluteJoint}
import sims.geometry.{PortableMath, Vector2D}
import sims.solver.SoftStep

/** A windmill: a rotor of four blades on one body, pinned to the top of a fixed tower by a
  * revolute joint whose motor turns it clockwise at `Motor.speed` with at most `Motor.maxForce`,
  * and balls dropped one by one onto it from above: the blades strike them and throw them
  * sideways, and the motor holds the rotor's speed through the blows. Soft step only: the
  * classic step has no motor.
  */
object Windmill extends Scene:
  /** The rotor's hub, on top of the tower, m. */
  val Hub: Vector2D = Vector2D(0, 4.5)
  /** Blades, how far each reaches from the hub, m, their half thickness, m, and density, kg/m^2. */
  val Blades: Int = 4
  val BladeReach: Double = 1.7
  val BladeHalfThickness: Double = 0.07
  val BladeDensity: Double = 2
  /** The motor: clockwise, rad/s, with at most this torque, N m. */
  val Motor: JointMotor = JointMotor(speed = -1.5, maxForce = 400)
  /** Balls dropped, one every `DropInterval` steps from `DropHeight`, and their radius, m. */
  val Balls: Int = 30
  val DropInterval: Int = 20
  val DropHeight: Double = 9
  val BallRadius: Double = 0.2
  /** Where the balls are dropped: at most this far left or right of the hub, m. */
  val DropSpread: Double = 1.2

  def name: String = "Windmill"
  def description: String = "A motor turns a windmill's four-bladed rotor at a steady speed; it knocks away the balls dropped on it."
  def view: Region = Region(-9, -0.5, 9, 10)
  override def region: Region = Region(-8, -0.2, 8, 10)
  override def softStepOnly: Boolean = true

  /** Where the `i`-th ball is dropped (0 first): spread over the rotor, left and right of the hub. */
  def dropPoint(i: Int): Vector2D = Vector2D(Hub.x + DropSpread * (((i * 7) % 9) - 4) / 4.0, DropHeight)

  /** A world that drops the scene's balls, with its rotor and its motor's joint. */
  final class WindmillWorld extends World:
    solver = SoftStep()
    /** The rotor: the blades on one body, turning about the hub. */
    val rotor: Body = Body((0 until Blades).map(blade)*)
    /** The pin of the rotor to the tower, with the motor. */
    val axle: RevoluteJoint =
      val tower = Scene.fixedBox(Vector2D(Hub.x, Hub.y / 2), 0.25, Hub.y / 2)
      this += tower
      this += rotor
      val joint = RevoluteJoint(tower, rotor, Hub)
      joint.collideConnected = false // the blades sweep past the tower
      joint.motor = Some(Motor)
      this += joint
      joint
    /** The balls dropped so far, in order. */
    val balls: collection.mutable.ArrayBuffer[Body] = collection.mutable.ArrayBuffer.empty
    private var steps = 0

    override def postStep(): Unit =
      steps += 1
      if steps % DropInterval == 0 && balls.size < Balls then
        val ball = Scene.ball(dropPoint(balls.size), BallRadius)
        ball.shapes.head.restitution = 0.3
        this += ball
        balls += ball

  /** Blade `k` of the rotor, a thin plank from the hub outwards, the first pointing up and right. */
  private def blade(k: Int): Shape =
    val angle = math.Pi / 4 + k * 2 * math.Pi / Blades
    val along = Vector2D(PortableMath.cos(angle), PortableMath.sin(angle))
    val plank = Rectangle(BladeReach / 2, BladeHalfThickness, BladeDensity)
    plank.pos = Hub + along * (BladeReach / 2)
    plank.rotation = angle
    plank

  def build(): Staged =
    val world = WindmillWorld()
    Scene.container(9, 8, 2).foreach(world += _)
    Staged(world)
