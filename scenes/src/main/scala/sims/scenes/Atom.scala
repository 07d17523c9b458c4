package sims.scenes

import sims.dynamics.joints.SpringJoint
import sims.geometry.{PortableMath, Vector2D}

/** A model atom without gravity: electrons on springs orbit a heavy nucleus. */
object Atom extends Scene:
  /** Number of electrons. */
  val Electrons = 6
  private val OrbitRadius = 2.5

  def name: String = "Atom"
  def description: String = s"$Electrons electrons on springs orbiting a nucleus, no gravity."
  def view: Region = Region(-5, -4, 5, 4)
  override def region: Region = Region(-8, -8, 8, 8)

  def build(): Staged =
    val world = sims.dynamics.World()
    world.gravity = Vector2D.Null
    val nucleus = Scene.ball(Vector2D.Null, 0.6, density = 20)
    world += nucleus
    for i <- 0 until Electrons do
      val angle = 2 * math.Pi * i / Electrons
      val radius = OrbitRadius + 0.4 * (i % 2)
      val electron = Scene.ball(Vector2D(radius * PortableMath.cos(angle), radius * PortableMath.sin(angle)), 0.15)
      // Tangential velocity, alternating in size so the orbits precess and the picture moves.
      electron.linearVelocity = Vector2D(-PortableMath.sin(angle), PortableMath.cos(angle)) * (5 + i % 3)
      world += electron
      world += SpringJoint(nucleus, electron, 8)
    Staged(world)
