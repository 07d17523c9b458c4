package sims.bench

import sims.dynamics.{Body, World}
import sims.dynamics.joints.{DistanceJoint, RevoluteJoint}
import sims.scenes.Scene
import sims.solver.{ClassicStep, Solver}

/** Builds a scene in SiMS: the scene's own world (a layout's as `sims.scenes.Layout.world`
  * makes it), with the bench's iterations, the solver asked for and sleeping off.
  */
object SimsBuilder:
  private final class Built(val world: World, val dynamic: IndexedSeq[Body]) extends EngineScene:
    def step(): Unit = world.step()
    def dynamicStates: Array[Double] =
      dynamic.flatMap(b => Seq(b.pos.x, b.pos.y, b.rotation)).toArray
    def dynamicVelocities: Array[Double] =
      dynamic.flatMap(b => Seq(b.linearVelocity.x, b.linearVelocity.y, b.angularVelocity)).toArray
    def jointLengths: Array[Double] =
      world.joints.collect { case j: DistanceJoint => (j.connection2 - j.connection1).length }.toArray
    def pinGaps: Array[Double] = world.joints.collect { case j: RevoluteJoint => j.separation }.toArray

  /** The scene's world with the bench's settings and `solver` (for tools that look inside a
    * SiMS step).
    */
  def world(scene: Scene, solver: Solver = ClassicStep): World =
    val world = scene.build().world
    world.iterations = Settings.Iterations
    world.solver = solver
    // The bench measures the step's work: no body falls asleep (the peers' sleeping is off too).
    world.enableSleep = false
    world

  /** Builds the scene, stepped by `solver`. */
  def build(scene: Scene, solver: Solver = ClassicStep): EngineScene =
    val built = world(scene, solver)
    Built(built, built.bodies.filterNot(_.fixed).toIndexedSeq)
