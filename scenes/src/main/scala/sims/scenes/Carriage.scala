package sims.scenes

import sims.dynamics.Body
import sims.dynamics.joints.{DistanceJoint, SpringJoint}
import sims.geometry.{PortableMath, Vector2D}

/** A car rolling down a slope into a valley: a chassis and two wheels, each wheel hung on a
  * swinging arm (a distance joint) and held up by a damped spring, so it moves up and down
  * relative to the chassis while it turns freely (the arm is anchored at the wheel's centre).
  */
object Carriage extends Scene:
  private val WheelRadius = 0.4
  /** Spring constant of each wheel's suspension, N/m. */
  val SuspensionStiffness = 120.0
  /** Damping of each wheel's suspension, N s/m. */
  val SuspensionDamping = 3.0

  def name: String = "Carriage"
  def description: String = "A car with sprung wheels rolling down a slope."
  def view: Region = Region(-11, -1, 17, 8)
  override def region: Region = Region(-11, -0.5, 17, 10)

  def build(): Staged =
    val world = sims.dynamics.World()
    val slopeTop = Vector2D(-10, 3)
    val valleyLeft = Vector2D(0, 0)
    world += Scene.ramp(slopeTop, valleyLeft)
    world += Scene.ramp(Vector2D(-0.5, 0), Vector2D(6.5, 0))
    world += Scene.ramp(Vector2D(6, 0), Vector2D(16, 3))
    // The car is built in the slope's frame: x along the surface, y along its normal.
    val along = (valleyLeft - slopeTop).unit
    val up = along.leftNormal
    val origin = slopeTop + along * 2
    def at(x: Double, y: Double): Vector2D = origin + along * x + up * y
    val chassisShape = sims.dynamics.Rectangle(1.0, 0.2, 2)
    chassisShape.pos = at(0, 1.05)
    chassisShape.rotation = PortableMath.atan2(along.y, along.x)
    val chassis = chassisShape.asBody
    world += chassis
    for side <- Seq(-1, 1) do
      val wheel: Body = Scene.ball(at(0.8 * side, WheelRadius + 0.02), WheelRadius)
      wheel.shapes.head.friction = 1
      // The wheels hang under the chassis; they must not collide with it.
      wheel.shapes.head.transientShapes += chassisShape
      world += wheel
      world += DistanceJoint(chassis, at(0.1 * side, 0.85), wheel, wheel.pos)
      val springTop = at(0.8 * side, 0.85)
      // Rest length a little longer than at creation: the springs start carrying the load.
      val spring = SpringJoint(chassis, springTop, wheel, wheel.pos, SuspensionStiffness,
        (wheel.pos - springTop).length + 0.08)
      spring.damping = SuspensionDamping
      world += spring
    Staged(world)
