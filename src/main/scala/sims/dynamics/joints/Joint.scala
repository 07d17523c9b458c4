package sims.dynamics.joints

import sims.dynamics.{Body, Constraint, World}

/** A constraint between two bodies, `node1` and `node2` (documentation 4.9). */
abstract class Joint extends Constraint:
  /** The first body. */
  val node1: Body

  /** The second body. */
  val node2: Body

  private var _collideConnected = sims.Defaults.CollideConnected

  /** Whether `node1` and `node2` collide with each other (default true, as in SiMS 1.2; Box2D's
    * joints default to false). Setting it takes effect at the next step, in a world or not.
    */
  def collideConnected: Boolean = _collideConnected

  /** Lets the two bodies collide with each other (true) or not (false). */
  def collideConnected_=(value: Boolean): Unit =
    if value != _collideConnected then
      _collideConnected = value
      if world != null then keepApart(!value)

  /** The world this joint is in, or null. */
  private[sims] var world: World = null

  /** Records (`apart` true) or forgets (false) on both bodies that this joint keeps them from
    * colliding; the world calls it when a joint with `collideConnected` false joins or leaves.
    */
  private[sims] def keepApart(apart: Boolean): Unit =
    if apart then
      node1.addJointPartner(node2)
      node2.addJointPartner(node1)
    else
      node1.removeJointPartner(node2)
      node2.removeJointPartner(node1)

  /** Fails unless the two bodies exist and differ; called by every joint's constructor. */
  protected def checkNodes(): Unit =
    if node1 == null then throw IllegalArgumentException("node1 must not be null")
    if node2 == null then throw IllegalArgumentException("node2 must not be null")
    if node1 eq node2 then throw IllegalArgumentException(s"a joint needs two different bodies, got $node1 twice")

  /** Whether the bodies this joint moves are in `world`; `World.step` fails unless they are.
    * A joint with an internal body that belongs to no world (the MouseJoint's ground) overrides it.
    */
  private[sims] def bodiesIn(world: World): Boolean = (node1.world eq world) && (node2.world eq world)

  /** Why this joint cannot be stepped by a solver that integrates forces over intervals of `h`
    * seconds (its force interval; `solverName` for the message), or None. A spring too stiff
    * for the interval diverges (see [[SpringJoint]]); the world checks this when the joint joins
    * it and before every step.
    */
  private[sims] def forceIntervalProblem(h: Double, solverName: String): Option[String] = None
