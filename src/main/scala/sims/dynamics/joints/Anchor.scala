package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.{PortableMath, Vector2D}

/** A point fixed on a body, where a joint attaches (SiMS 1.2, docs/constraints.md): its offset from the body's
  * centre and the body's rotation at creation, so that its current arm is that offset rotated
  * by the change of rotation since. Immutable: each step that needs the current arm keeps its
  * own [[AnchorArm]] (`arm()`), so the two steps never share a field.
  */
private[sims] final class Anchor(val body: Body, point: Vector2D):
  /** Offset from the body's centre at creation, world frame then. */
  val offsetX: Double = point.x - body.x
  val offsetY: Double = point.y - body.y
  /** The body's rotation at creation. */
  val rotationAtCreation: Double = body.rotation

  /** A new arm of this point, computed for the body's current rotation. */
  def arm(): AnchorArm = AnchorArm(this)

/** The arm of an [[Anchor]] at its body's rotation, as two doubles for the solvers (no
  * allocation); the cosine and sine are recomputed only when the body has turned.
  */
private[sims] final class AnchorArm(anchor: Anchor):
  private var turnedAngle = Double.NaN // the body rotation the arm was last computed for
  private var c, s = 0.0

  /** Arm from the centre of mass to the point, world frame, as of the last `update()`. */
  var armX, armY: Double = 0

  update()

  /** Recomputes the arm for the body's current rotation (the expressions of `Vector2D.rotate`). */
  def update(): Unit = updateFor(anchor.body.angle)

  /** Recomputes the arm for the body at rotation `angle`. */
  def updateFor(angle: Double): Unit =
    // NaN never equals itself, so the first call and a non-finite rotation always recompute.
    if angle != turnedAngle then
      val turn = angle - anchor.rotationAtCreation
      c = PortableMath.cos(turn)
      s = PortableMath.sin(turn)
      turnedAngle = angle
    armX = anchor.offsetX * c - anchor.offsetY * s
    armY = anchor.offsetX * s + anchor.offsetY * c

  /** World x coordinate of the point, as of the last `update()` of the arm. */
  def x: Double = anchor.body.x + armX

  /** World y coordinate of the point, as of the last `update()` of the arm. */
  def y: Double = anchor.body.y + armY

  /** Current world position of the point (updates the arm). */
  def position: Vector2D =
    update()
    Vector2D(x, y)

  /** Current offset from the body's centre of mass (updates the arm). */
  def arm: Vector2D =
    update()
    Vector2D(armX, armY)
