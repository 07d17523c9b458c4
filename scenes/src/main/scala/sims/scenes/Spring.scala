package sims.scenes

import sims.dynamics.joints.SpringJoint
import sims.geometry.Vector2D

/** A particle hanging from a fixed point on a damped spring, released off its rest position
  * so it swings and bounces.
  */
object Spring extends Scene:
  /** Spring constant, N/m. */
  val SpringConstant = 30.0
  /** Damping, N s/m. */
  val Damping = 0.3

  def name: String = "Spring"
  def description: String = "A particle on a damped spring."
  def view: Region = Region(-4, -5, 4, 1)

  def build(): Staged =
    val world = sims.dynamics.World()
    world.enableCollisionDetection = false
    val anchor = Scene.ball(Vector2D(0, 0), 0.1)
    anchor.fixed = true
    val particle = Scene.ball(Vector2D(1.5, -1), 0.2, density = 10)
    world += anchor
    world += particle
    // Rest length 1 m: the particle starts stretched sideways and swings while oscillating.
    val spring = SpringJoint(anchor, anchor.pos, particle, particle.pos, SpringConstant, 1.0)
    spring.damping = Damping
    world += spring
    Staged(world)
