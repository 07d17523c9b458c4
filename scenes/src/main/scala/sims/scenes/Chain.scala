package sims.scenes

import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

/** A chain of 20 nodes linked by distance joints between two fixed ends; a large, light
  * ball falls into it.
  */
object Chain extends Scene:
  /** Number of free nodes between the fixed ends. */
  val Nodes = 20
  private val Spacing = 0.4
  private val NodeRadius = 0.1

  def name: String = "Chain"
  def description: String = s"$Nodes nodes between two fixed ends, a large light ball dropped on them."
  def view: Region = Region(-6, -6, 6, 4)
  override def region: Region = Region(-6, -8, 6, 6)

  def build(): Staged =
    val world = sims.dynamics.World()
    val left = -(Nodes + 1) * Spacing / 2
    val nodes =
      for i <- 0 to Nodes + 1 yield
        val node = Scene.ball(Vector2D(left + i * Spacing, 0), NodeRadius, density = 10)
        node.fixed = i == 0 || i == Nodes + 1
        world += node
        node
    for Seq(a, b) <- nodes.sliding(2) do world += DistanceJoint(a, a.pos, b, b.pos)
    world += Scene.ball(Vector2D(0.3, 3), 1.0, density = 0.2)
    Staged(world)
