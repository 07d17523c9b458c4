package sims.scenes

import sims.geometry.Vector2D
import sims.prefabs.Net

/** The Net prefab, 10 x 10 nodes, hanging from one fixed corner and swinging down. */
object NetScene extends Scene:
  def name: String = "Net"
  def description: String = "A net of 10 x 10 nodes linked by distance joints, one corner fixed."
  def view: Region = Region(-5, -5, 5, 3)
  override def region: Region = Region(-6, -6, 6, 4)

  def build(): Staged =
    val world = sims.dynamics.World()
    val net = Net(10, 10, Vector2D(0, -0.5))
    net.node(0, 9).fixed = true
    net.addTo(world)
    Staged(world)
