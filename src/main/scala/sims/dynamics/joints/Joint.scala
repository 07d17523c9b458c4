package sims.dynamics.joints

import sims.dynamics.{Body, Constraint, World}
import sims.solver.soft.{JointRows, SoftContext}

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

  // ---- The soft step (SOFTSTEP.md section 3). The built-in joints override these with their
  // soft constraint; a joint that does not (a user's own) is solved by its classic
  // `correctVelocity` in every solve and relax pass of every substep, on the bodies' current
  // velocities and placements. `correctPosition` is never called by the soft step.

  /** The impulses this joint accumulated in the soft step, carried to the next step (warm
    * starting); one per row of the constraint, empty for joints without them.
    */
  private[sims] def softImpulse: Array[Double] = Joint.NoImpulse

  /** Whether the soft step applies this joint's forces in every substep (a `ForceJoint`'s, at
    * the substep's placements), rather than solving it as a constraint.
    */
  private[sims] def softForces: Boolean = this.isInstanceOf[ForceJoint]

  /** Soft step: takes what stays fixed during the step, with the bodies at their placements
    * at its start.
    */
  private[sims] def prepareSoft(context: SoftContext): Unit = ()

  /** Soft step: the number of rows this joint gives the direct solver of joint trees
    * (`rowsSoft`), or 0 when it is solved iteratively by `solveSoft`.
    */
  private[sims] def directRows: Int = 0

  /** Soft step: the joint's rows at the current substep, for the direct solver. */
  private[sims] def rowsSoft(context: SoftContext, rows: JointRows): Unit = ()

  /** Soft step: applies the impulses accumulated so far. */
  private[sims] def warmStartSoft(context: SoftContext): Unit = ()

  /** Soft step: one pass of the constraint, with the soft bias (`useBias`, the solve pass) or
    * without (the relax pass). By default the classic velocity correction.
    */
  private[sims] def solveSoft(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val i1 = node1.index
    val i2 = node2.index
    if i1 >= 0 then bodies.expose(i1)
    if i2 >= 0 then bodies.expose(i2)
    correctVelocity(context.h)
    if i1 >= 0 then bodies.absorb(i1)
    if i2 >= 0 then bodies.absorb(i2)

private[sims] object Joint:
  private val NoImpulse = new Array[Double](0)
