package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** A point fixed on a body, like [[Anchor]], whose arm (offset from the centre of mass) is kept
  * as two doubles so that the solvers of the point joints run without allocating: call
  * `update()` once the body has moved, then read `armX`, `armY`, `x`, `y`.
  */
private[joints] final class BodyPoint(val body: Body, point: Vector2D):
  // Offset in the body's own frame (body rotation 0), so that the current arm is one rotation.
  private val localOffset = (point - body.pos).rotate(-body.rotation)
  private val localX = localOffset.x
  private val localY = localOffset.y

  /** Arm from the centre of mass to the point, world frame, as of the last `update()`. */
  var armX, armY: Double = 0

  update()

  /** Recomputes the arm from the body's current rotation. */
  def update(): Unit =
    val c = math.cos(body.rotation)
    val s = math.sin(body.rotation)
    armX = localX * c - localY * s
    armY = localX * s + localY * c

  /** World x coordinate of the point, as of the last `update()` of the arm. */
  def x: Double = body.x + armX

  /** World y coordinate of the point, as of the last `update()` of the arm. */
  def y: Double = body.y + armY

  /** Current world position of the point (updates the arm). */
  def position: Vector2D =
    update()
    Vector2D(x, y)
