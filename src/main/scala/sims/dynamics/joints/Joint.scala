package sims.dynamics.joints

import sims.dynamics.{Body, Constraint, World}

/** A constraint between two bodies, `node1` and `node2` (documentation 4.9). */
abstract class Joint extends Constraint:
  /** The first body. */
  val node1: Body

  /** The second body. */
  val node2: Body

  /** Fails unless the two bodies exist and differ; called by every joint's constructor. */
  protected def checkNodes(): Unit =
    if node1 == null then throw IllegalArgumentException("node1 must not be null")
    if node2 == null then throw IllegalArgumentException("node2 must not be null")
    if node1 eq node2 then throw IllegalArgumentException(s"a joint needs two different bodies, got $node1 twice")

  /** Whether the bodies this joint moves are in `world`; `World.step` fails unless they are.
    * A joint with an internal body that belongs to no world (the MouseJoint's ground) overrides it.
    */
  private[sims] def bodiesIn(world: World): Boolean = (node1.world eq world) && (node2.world eq world)
