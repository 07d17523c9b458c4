package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.{PortableMath, Vector2D}

/** A point fixed on a body, where a joint attaches (SPEC section 3): stored as its offset from
  * the body's centre and the body's rotation at creation, so its current arm is that offset
  * rotated by the change of rotation since. `update()` computes the arm as two doubles for the
  * solvers (no allocation); the cosine and sine are recomputed only when the body has turned.
  */
private[joints] final class Anchor(val body: Body, point: Vector2D):
  private val offsetX = point.x - body.x
  private val offsetY = point.y - body.y
  private val rotationAtCreation = body.rotation
  private var turnedAngle = Double.NaN // the body rotation the arm was last computed for
  private var c, s = 0.0

  /** Arm from the centre of mass to the point, world frame, as of the last `update()`. */
  var armX, armY: Double = 0

  update()

  /** Recomputes the arm for the body's current rotation (the expressions of `Vector2D.rotate`). */
  def update(): Unit = updateFor(body.angle)

  /** Recomputes the arm for the body at rotation `angle`. */
  def updateFor(angle: Double): Unit =
    // NaN never equals itself, so the first call and a non-finite rotation always recompute.
    if angle != turnedAngle then
      val turn = angle - rotationAtCreation
      c = PortableMath.cos(turn)
      s = PortableMath.sin(turn)
      turnedAngle = angle
    armX = offsetX * c - offsetY * s
    armY = offsetX * s + offsetY * c

  /** World x coordinate of the point, as of the last `update()` of the arm. */
  def x: Double = body.x + armX

  /** World y coordinate of the point, as of the last `update()` of the arm. */
  def y: Double = body.y + armY

  /** Current world position of the point (updates the arm). */
  def position: Vector2D =
    update()
    Vector2D(x, y)

  /** Current offset from the body's centre of mass (updates the arm). */
  def arm: Vector2D =
    update()
    Vector2D(armX, armY)
