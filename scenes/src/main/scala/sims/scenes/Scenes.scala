package sims.scenes

/** The registry of all example scenes, in a fixed order (the original's first). */
object Scenes:
  /** Every scene, in the order the viewer and the listing show them. */
  val all: IndexedSeq[Scene] = IndexedSeq(
    BallStack, Chain, Stacking, Restitution, Friction, Spring, NetScene, Cup, Carriage, Wave,
    Atom, Cannon, PylonScene, RagdollScene, CompositeShape, Pyramid, Pile, NewtonsCradle, Dominoes, Queries, Filtering,
    Shapes, Sensors, Bullet, Platformer, LimitedRagdoll, Car, Bridge, Windmill)

  /** The scene run when none is named. */
  val default: Scene = BallStack

  /** The scene with this name, ignoring case, if there is one: an example scene, else a
    * benchmark scene ([[BenchScenes.find]]), else a test scene ([[TestScenes.find]]).
    */
  def find(name: String): Option[Scene] =
    all.find(_.name.equalsIgnoreCase(name)).orElse(BenchScenes.find(name)).orElse(TestScenes.find(name))
