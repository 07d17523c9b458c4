package sims.scenes

import sims.dynamics.{Body, World}
import sims.geometry.Vector2D

/** Kinematic platforms: one glides from side to side, one rises and sinks as a lift, each at
  * a steady speed turned round every `Half` steps, and the boxes standing on them ride along by
  * friction (1 on both, so a pair's is 1). The platforms move by their velocities alone: the boxes' weight and contacts never
  * push them. Runs under either step.
  */
object Platformer extends Scene:
  /** The platforms' speed, m/s. */
  val Speed: Double = 0.6
  /** Steps between two turns of the platforms. */
  val Half: Int = 90
  /** Where the gliding platform starts and the lift starts, m. */
  val GliderStart: Vector2D = Vector2D(-3, 1.5)
  val LiftStart: Vector2D = Vector2D(3, 0.5)
  /** A platform's half width and half height, m. */
  val PlatformHalfWidth: Double = 1.0
  val PlatformHalfHeight: Double = 0.1
  /** A box's half side, m. */
  val BoxHalf: Double = 0.25

  def name: String = "Platformer"
  def description: String = "Kinematic platforms, one gliding sideways and one lifting, carry the boxes on them by friction."
  def view: Region = Region(-6, -0.5, 6, 5.5)

  /** A world whose platforms turn round every `Half` steps. */
  final class PlatformWorld extends World:
    /** The platform that glides from side to side. */
    val glider: Body = Scene.box(GliderStart, PlatformHalfWidth, PlatformHalfHeight)
    /** The platform that rises and sinks. */
    val lift: Body = Scene.box(LiftStart, PlatformHalfWidth, PlatformHalfHeight)
    /** The boxes, two on the glider and one on the lift. */
    val boxes: Seq[Body] = Seq(
      Scene.box(GliderStart + Vector2D(-0.4, PlatformHalfHeight + BoxHalf + 0.005), BoxHalf, BoxHalf),
      Scene.box(GliderStart + Vector2D(0.4, PlatformHalfHeight + BoxHalf + 0.005), BoxHalf, BoxHalf),
      Scene.box(LiftStart + Vector2D(0, PlatformHalfHeight + BoxHalf + 0.005), BoxHalf, BoxHalf))
    private var steps = 0

    override def postStep(): Unit =
      steps += 1
      if steps % Half == 0 then
        glider.linearVelocity = -glider.linearVelocity
        lift.linearVelocity = -lift.linearVelocity

  def build(): Staged =
    val world = PlatformWorld()
    world += Scene.ground(6)
    for (platform, velocity) <- Seq(world.glider -> Vector2D(Speed, 0), world.lift -> Vector2D(0, Speed)) do
      platform.kinematic = true
      platform.linearVelocity = velocity
      platform.shapes.head.friction = 1
      world += platform
    for box <- world.boxes do
      box.shapes.head.friction = 1
      world += box
    Staged(world)
