package sims.scenes

import sims.dynamics.Body
import sims.dynamics.joints.{PrismaticJoint, SpringJoint}
import sims.geometry.{PortableMath, Vector2D}

/** A transverse wave: particles that may only slide up and down their vertical rails
  * (prismatic joints), each pulled towards its neighbours by a stretched spring. A pulse
  * starts at the left and is reflected by the fixed ends; the action plucks the string again.
  */
object Wave extends Scene:
  /** Number of moving particles between the two fixed ends. */
  val Particles = 25
  private val Spacing = 0.4
  /** Spring constant between neighbours, N/m. */
  val SpringConstant = 40.0
  // Shorter than the spacing: the springs are under tension, which carries transverse waves.
  private val RestLength = 0.2
  private val RailY = -2.0

  def name: String = "Wave"
  def description: String = s"$Particles particles on prismatic rails coupled by springs: a travelling pulse."
  def view: Region = Region(-6, -3, 6, 3)

  /** Gives the particles near the left end an upward push. */
  def pluck(particles: Seq[Body]): Unit =
    for (particle, i) <- particles.take(5).zipWithIndex do
      particle.linearVelocity = particle.linearVelocity + Vector2D(0, 3.0 * PortableMath.sin(math.Pi * (i + 1) / 6))

  def build(): Staged =
    val world = sims.dynamics.World()
    world.gravity = Vector2D.Null
    // The particles only meet through their springs; no contacts to compute.
    world.enableCollisionDetection = false
    val left = -(Particles + 1) * Spacing / 2
    val frame = Scene.fixedBox(Vector2D(0, RailY), (Particles + 1) * Spacing / 2 + 0.2, 0.05)
    frame.shapes.head.collidable = false
    world += frame
    val nodes =
      for i <- 0 to Particles + 1 yield
        val node = Scene.ball(Vector2D(left + i * Spacing, 0), 0.1, density = 10)
        node.fixed = i == 0 || i == Particles + 1
        world += node
        node
    val particles = nodes.slice(1, Particles + 1)
    for particle <- particles do
      world += PrismaticJoint(frame, Vector2D(particle.pos.x, RailY), particle, particle.pos)
    for Seq(a, b) <- nodes.sliding(2) do world += SpringJoint(a, a.pos, b, b.pos, SpringConstant, RestLength)
    pluck(particles)
    Staged(world, Some(SceneAction("Pluck", () => pluck(particles))))
