package sims.dynamics.joints

import sims.dynamics.{Body, Constraint, World}
import sims.geometry.Vector2D

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

  /** Anything of the user's that belongs with this joint (default None): never read by the library. */
  var userData: Option[Any] = None

  private var _name: Option[String] = None

  /** The joint's name (default None), kept by save and load: `World.jointNamed` finds it. */
  def name: Option[String] = _name

  /** Names the joint (or takes its name away with None); a name must not be null. */
  def name_=(value: Option[String]): Unit =
    if value == null || value.exists(_ == null) then throw IllegalArgumentException("name must not be null, use None")
    _name = value

  // The reaction of the last soft step, set by its constraint: force on node2, N, torque, N m.
  private[sims] var reactionX, reactionY, reactionTurn: Double = 0

  /** The force this joint applied to `node2` in the last step (node1 got the opposite), N:
    * measured by the soft step from the impulses it applied; Vector2D.Zero before any soft
    * step (the classic step, SiMS 1.2's, does not measure it).
    */
  def reactionForce: Vector2D = Vector2D(reactionX, reactionY)

  /** The torque this joint applied to `node2` in the last step about its centre, beyond that of
    * `reactionForce` (its limits, motor, spring or angular constraint), N m; as `reactionForce`.
    */
  def reactionTorque: Double = reactionTurn

  private var _breakForce = Double.PositiveInfinity
  private var _breakTorque = Double.PositiveInfinity

  /** The joint breaks (the world removes it after the step and reports a
    * [[sims.dynamics.JointBreak]] in `World.jointBreaks`) once the length of its
    * `reactionForce` exceeds this, N; default infinite (it never breaks). Needs the soft step.
    */
  def breakForce: Double = _breakForce

  /** Sets the force at which the joint breaks; must be positive (infinite: never). */
  def breakForce_=(value: Double): Unit =
    if !(value > 0) then throw IllegalArgumentException(s"breakForce must be positive, got $value")
    _breakForce = value

  /** As `breakForce`, for the size of `reactionTorque`, N m; default infinite. */
  def breakTorque: Double = _breakTorque

  /** Sets the torque at which the joint breaks; must be positive (infinite: never). */
  def breakTorque_=(value: Double): Unit =
    if !(value > 0) then throw IllegalArgumentException(s"breakTorque must be positive, got $value")
    _breakTorque = value

  /** Whether the last step's reaction exceeds `breakForce` or `breakTorque`. */
  private[sims] def overloaded: Boolean =
    reactionX * reactionX + reactionY * reactionY > _breakForce * _breakForce || math.abs(reactionTurn) > _breakTorque

  /** What of this joint only the soft step can step (a motor, a spring, a break force), or None:
    * the world refuses such a joint under [[sims.solver.ClassicStep]], whose SiMS 1.2 algorithm
    * has no measure of a joint's load nor a soft constraint to extend.
    */
  private[sims] def softStepFeature: Option[String] =
    if _breakForce.isFinite || _breakTorque.isFinite then Some("a breakForce or breakTorque") else None

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
    * seconds (its force interval; `solver` is named in the message), or None. A spring too stiff
    * for the interval diverges (see [[SpringJoint]]); the world checks this when the joint joins
    * it and before every step, so the check allocates nothing unless it fails.
    */
  private[sims] def forceIntervalProblem(h: Double, solver: AnyRef): Option[String] = None
