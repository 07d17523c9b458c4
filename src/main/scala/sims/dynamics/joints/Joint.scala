package sims.dynamics.joints

import sims.dynamics.{Body, Constraint, World}
import sims.geometry.Vector2D

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

/** A point fixed on a body: stored relative to the body's centre and rotation at creation,
  * it moves and turns with the body. `update()` computes the current arm as two doubles for
  * the solvers; the cosine and sine are recomputed only when the body has turned since.
  */
private[joints] final class Anchor(body: Body, point: Vector2D):
  private val offset = point - body.pos
  private val rotationAtCreation = body.rotation
  private var turnedAngle = Double.NaN // the body rotation the arm was last computed for
  private var c, s = 0.0

  /** Arm from the centre of mass to the point, world frame, as of the last `update()`. */
  var armX, armY: Double = 0

  /** Recomputes the arm for the body's current rotation (the expressions of `Vector2D.rotate`). */
  def update(): Unit =
    val angle = body.angle
    // NaN never equals itself, so the first call and a non-finite rotation always recompute.
    if angle != turnedAngle then
      val turn = angle - rotationAtCreation
      c = math.cos(turn)
      s = math.sin(turn)
      turnedAngle = angle
    armX = offset.x * c - offset.y * s
    armY = offset.x * s + offset.y * c

  /** Current world position of the point. */
  def position: Vector2D =
    update()
    Vector2D(body.x + armX, body.y + armY)

  /** Current offset from the body's centre of mass. */
  def arm: Vector2D =
    update()
    Vector2D(armX, armY)
