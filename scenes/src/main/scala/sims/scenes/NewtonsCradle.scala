package sims.scenes

import sims.dynamics.joints.DistanceJoint
import sims.geometry.{PortableMath, Vector2D}

/** Five steel balls on pendulums, the first lifted and let go (restitution 1). */
object NewtonsCradle extends Scene:
  /** Number of balls. */
  val Balls = 5
  private val Radius = 0.3
  private val Length = 2.5

  def name: String = "NewtonsCradle"
  def description: String = s"Newton's cradle: $Balls balls on distance-joint pendulums."
  def view: Region = Region(-4, -3.5, 4, 0.5)

  def build(): Staged =
    val world = sims.dynamics.World()
    for i <- 0 until Balls do
      val pivotX = (i - (Balls - 1) / 2.0) * 2 * Radius
      val pivot = Scene.ball(Vector2D(pivotX, 0), 0.05)
      pivot.fixed = true
      pivot.shapes.head.collidable = false
      // The first pendulum starts lifted by 60 degrees.
      val angle = if i == 0 then -math.Pi / 3 else 0.0
      val ball = Scene.ball(Vector2D(pivotX + Length * PortableMath.sin(angle), -Length * PortableMath.cos(angle)), Radius, density = 8)
      ball.shapes.head.restitution = 1
      world += pivot
      world += ball
      world += DistanceJoint(pivot, pivot.pos, ball, ball.pos)
    Staged(world)
