package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** Drives `node2` towards a placement relative to `node1`: its centre to `linearOffset` (in
  * node1's own frame, from node1's centre) and its rotation to node1's plus `angularOffset`,
  * with at most `maxForce` and `maxTorque`, closing `correctionFactor` of the gap per second and
  * step: a character pushed along a path, a platform that follows a mover, a top-down body with
  * friction against the ground. Box2D's motor joint; the soft step only (SiMS 1.2 has none).
  *
  * The rows: the relative turn Cdot = w2 - w1, bias = correctionFactor / h (theta2 - theta1 -
  * angularOffset), the impulse accumulated over the step clamped to maxTorque h per substep;
  * then the point C = x2 - (x1 + R1 linearOffset), Cdot = v2 - v1 - w1 x (x2 - x1) (the
  * impulse acts at node2's centre on both bodies), bias correctionFactor / h C, the accumulated
  * impulse's length clamped to maxForce h.
  *
  * @param linearOffset node2's target centre in node1's frame, m (default: where it is now)
  * @param angularOffset node2's target rotation relative to node1's, rad (default: as now)
  * @param maxForce the largest force it may use, N, at least 0
  * @param maxTorque the largest torque it may use, N m, at least 0
  * @param correctionFactor the part of the gap closed per step, 0 to 1
  */
final class MotorJoint(val node1: Body, val node2: Body, linearOffset: Option[Vector2D] = None,
    angularOffset: Option[Double] = None, val maxForce: Double = 1000, val maxTorque: Double = 1000,
    val correctionFactor: Double = 0.3) extends Joint:
  checkNodes()
  if !(maxForce >= 0) || maxForce.isInfinite then
    throw IllegalArgumentException(s"maxForce must be finite and at least 0, got $maxForce")
  if !(maxTorque >= 0) || maxTorque.isInfinite then
    throw IllegalArgumentException(s"maxTorque must be finite and at least 0, got $maxTorque")
  if !(correctionFactor >= 0 && correctionFactor <= 1) then
    throw IllegalArgumentException(s"correctionFactor must be between 0 and 1, got $correctionFactor")
  linearOffset.foreach(Vector2D.requireFinite("linearOffset", _))
  angularOffset.foreach(Vector2D.requireFinite("angularOffset", _))

  private var _linearOffset = linearOffset.getOrElse((node2.pos - node1.pos).rotate(-node1.rotation))
  private var _angularOffset = angularOffset.getOrElse(node2.rotation - node1.rotation)

  /** node2's target centre in node1's frame, m; may be changed at any time (a mover's path). */
  def targetOffset: Vector2D = _linearOffset

  /** Sets the target centre; must be finite. */
  def targetOffset_=(value: Vector2D): Unit = _linearOffset = Vector2D.requireFinite("targetOffset", value)

  /** node2's target rotation relative to node1's, rad; may be changed at any time. */
  def targetAngle: Double = _angularOffset

  /** Sets the target rotation; must be finite. */
  def targetAngle_=(value: Double): Unit = _angularOffset = Vector2D.requireFinite("targetAngle", value)

  override private[sims] def softStepFeature: Option[String] = Some("its kind (SiMS 1.2 has no motor joint)")

  /** Not stepped by the classic step: the world refuses a motor joint under it. */
  def correctVelocity(h: Double): Unit =
    throw UnsupportedOperationException("a MotorJoint is stepped by the soft step only (world.solver = SoftStep())")

  /** Not stepped by the classic step: the world refuses a motor joint under it. */
  def correctPosition(h: Double): Unit =
    throw UnsupportedOperationException("a MotorJoint is stepped by the soft step only (world.solver = SoftStep())")

  override def toString: String =
    s"MotorJoint($node1, $node2, targetOffset = ${_linearOffset}, targetAngle = ${_angularOffset}, " +
      s"maxForce = $maxForce, maxTorque = $maxTorque)"
