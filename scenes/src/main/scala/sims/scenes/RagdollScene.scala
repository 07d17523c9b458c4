package sims.scenes

import sims.dynamics.World
import sims.geometry.Vector2D
import sims.prefabs.Ragdoll

/** The Ragdoll prefab tumbling down a flight of stairs; the action drops another one. */
object RagdollScene extends Scene:
  private val Steps = 6
  private val StepWidth = 1.2
  private val StepHeight = 0.5

  def name: String = "Ragdoll"
  def description: String = "Ragdolls (9 bodies, 8 revolute joints each) tumbling down stairs (action: drop another)."
  def view: Region = Region(-1.5, -0.5, 9.5, 6)
  override def region: Region = Region(-3, -0.5, 16, 10)

  /** Where a dropped ragdoll starts, above the top step, and its velocity towards the stairs. */
  val DropPoint: Vector2D = Vector2D(0.3, Steps * StepHeight + 2.5)
  val DropVelocity: Vector2D = Vector2D(2.5, 0)

  /** Adds a ragdoll above the top step, pushed towards the stairs. */
  def drop(world: World): Unit =
    val ragdoll = Ragdoll(DropPoint)
    ragdoll.addTo(world)
    ragdoll.bodies.foreach(_.linearVelocity = DropVelocity)

  /** The ground and the stairs: step k's top is at height (Steps - k) * StepHeight, each step
    * one box down to the ground.
    */
  def stairs(): World =
    val world = Scene.worldOf(Scene.ground(9, centreX = 7))
    for k <- 0 until Steps do
      val height = (Steps - k) * StepHeight
      world += Scene.fixedBox(Vector2D(k * StepWidth + StepWidth / 2 - 0.6, height / 2), StepWidth / 2, height / 2)
    world

  def build(): Staged =
    val world = stairs()
    drop(world)
    Staged(world, Some(SceneAction("Drop", () => drop(world))))
