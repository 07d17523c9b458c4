package sims.prefabs

import sims.dynamics.{Body, World}
import sims.dynamics.joints.Joint

/** A ready-made assembly of bodies and joints (a net, a pylon, a ragdoll), as in the original. */
trait Prefab:
  /** The bodies of the assembly, in the order they are added to a world. */
  def bodies: Seq[Body]

  /** The joints of the assembly. */
  def joints: Seq[Joint]

  /** Adds all bodies, then all joints, to `world`. */
  def addTo(world: World): Unit =
    bodies.foreach(world += _)
    joints.foreach(world += _)
