package sims.scenes

import sims.geometry.Vector2D
import sims.prefabs.Pylon

/** The Pylon prefab, a truss of distance joints, standing on the ground; a ball hits its top. */
object PylonScene extends Scene:
  def name: String = "Pylon"
  def description: String = "A truss tower of nodes and distance joints on the ground, hit by a ball."
  def view: Region = Region(-8, -0.5, 8, 11)
  override def region: Region = Region(-14, -0.5, 14, 12)

  def build(): Staged =
    val world = Scene.worldOf(Scene.ground(14))
    val pylon = Pylon(Vector2D(-0.5, sims.Defaults.PylonNodeRadius), levels = 8)
    pylon.addTo(world)
    val ball = Scene.ball(Vector2D(-6, 8), 0.4, density = 5)
    ball.linearVelocity = Vector2D(6, 2)
    world += ball
    Staged(world)
