package sims.bench

import sims.dynamics.{Body, World}
import sims.dynamics.joints.DistanceJoint
import sims.scenes.Scene

/** Builds a scene in SiMS: the scene's own world (a layout's as `sims.scenes.Layout.world`
  * makes it), with the bench's iterations.
  */
object SimsBuilder:
  private final class Built(val world: World, val dynamic: IndexedSeq[Body]) extends EngineScene:
    def step(): Unit = world.step()
    def dynamicStates: Array[Double] =
      dynamic.flatMap(b => Seq(b.pos.x, b.pos.y, b.rotation)).toArray
    def jointLengths: Array[Double] =
      world.joints.collect { case j: DistanceJoint => (j.connection2 - j.connection1).length }.toArray

  /** The scene's world with the bench's settings (for tools that look inside a SiMS step). */
  def world(scene: Scene): World =
    val world = scene.build().world
    world.iterations = Settings.Iterations
    world

  /** Builds the scene. */
  def build(scene: Scene): EngineScene =
    val built = world(scene)
    Built(built, built.bodies.filterNot(_.fixed).toIndexedSeq)
