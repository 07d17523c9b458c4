package sims.dynamics.joints

import sims.Defaults

import sims.dynamics.{Body, Circle, World}
import sims.geometry.Vector2D

/** Pulls a point of a body towards a target point with a bounded force: what the viewer uses to
  * drag bodies with the mouse. Not part of the original SiMS.
  *
  * A hard constraint would yank a light body and fight a heavy one; this one is a stiff, damped
  * spring solved implicitly (a "soft constraint"), with stiffness k = m omega^2 and damping
  * c = 2 m zeta omega scaled by the body's mass m, so that every body follows the target with
  * the same `frequency` (omega = 2 pi frequency) and `dampingRatio` zeta, however light or heavy.
  *
  * Derivation, with p = x + r the grabbed point and t the target:
  *   C     = p - t
  *   Cdot  = v + w x r
  *   J     = [E, r.leftNormal]
  *   K = J M^-1 J^T = (1/m) E + 1/I [r.y^2, -r.x r.y; -r.x r.y, r.x^2]
  * The spring force F = -k C' - c Cdot', taken at the end of the step (C' = C + h Cdot', implicit
  * and hence stable for any k and h), gives for the step's impulse lambda = h F:
  *   Cdot' + (beta / h) C + gamma lambda = 0,  beta = h k / (c + h k),  gamma = 1 / (h (c + h k)).
  * Each velocity iteration solves (K + gamma E) dLambda = -(Cdot + (beta / h) C + gamma lambda)
  * for the step's impulse lambda so far, adds dLambda, and clamps |lambda| to maxForce h, which
  * bounds the force. The step's impulse restarts at 0 in phase 2 (`applyForce()`), which is why
  * this is a [[ForceJoint]]. There is no position correction: the spring is the position
  * correction, and a hard one would break the force bound.
  *
  * A body grabbed off its centre would swing or spin about the grabbed point for ever, and a
  * spinning body shakes the grabbed point; so the joint also damps the body's rotation while it
  * holds it, by the factor 1 / (1 + h angularDamping) once per step (implicit, so stable).
  *
  * `node2` is the dragged body. `node1` is an internal fixed body that sits at the target and is
  * in no world; it only gives the joint its two ends (a viewer may draw the line between them).
  *
  * @param body the dragged body
  * @param anchor the grabbed point, world coordinates at creation; it then moves with the body
  * @param maxForce bound of the force on the body, N; positive (infinity for no bound)
  */
final class MouseJoint(body: Body, anchor: Vector2D, val maxForce: Double) extends Joint with ForceJoint:
  if body == null then throw IllegalArgumentException("body must not be null")
  Vector2D.requireFinite("anchor", anchor)
  if !(maxForce > 0) then throw IllegalArgumentException(s"maxForce must be positive, got $maxForce")

  /** The dragged body. */
  val node2: Body = body

  /** A fixed body at the target, in no world: the other end of the joint. */
  val node1: Body =
    val ground = Circle(0.01, 1).asBody // its size does not matter: it only has to exist
    ground.pos = anchor
    ground.fixed = true
    ground

  checkNodes()

  /** The grabbed point on the dragged body (the soft step reads it too). */
  private[sims] val attachment = Anchor(node2, anchor)
  // The classic step's arm of the grabbed point.
  private val point = attachment.arm()

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor, node2, anchor)
  private var _target = anchor
  private var _frequency = Defaults.MouseFrequency
  private var _dampingRatio = Defaults.MouseDampingRatio
  private var _angularDamping = Defaults.MouseAngularDamping
  // True from phase 2 until the first velocity correction of the step.
  private var stepStarting = false
  // Impulse applied so far in the current step.
  private var impulseX, impulseY: Double = 0

  /** The point the grabbed point is pulled towards, world coordinates; initially the anchor. */
  def target: Vector2D = _target

  /** Moves the target (node1 follows); must be finite. */
  def target_=(point: Vector2D): Unit =
    _target = Vector2D.requireFinite("target", point)
    node1.pos = point

  /** Natural frequency of the spring, Hz (default 5): how fast the body follows the target. */
  def frequency: Double = _frequency

  /** Sets the frequency; must be positive and finite. */
  def frequency_=(value: Double): Unit =
    if !(value > 0) || value.isInfinite then
      throw IllegalArgumentException(s"frequency must be positive and finite, got $value")
    _frequency = value

  /** Damping ratio of the spring (default 0.7; 1 is critical damping). */
  def dampingRatio: Double = _dampingRatio

  /** Sets the damping ratio; must be finite and at least 0. */
  def dampingRatio_=(value: Double): Unit =
    if !(value >= 0) || value.isInfinite then
      throw IllegalArgumentException(s"dampingRatio must be finite and at least 0, got $value")
    _dampingRatio = value

  /** Damping of the body's rotation while dragged, 1/s (default 1); 0 for none. */
  def angularDamping: Double = _angularDamping

  /** Sets the angular damping; must be finite and at least 0. */
  def angularDamping_=(value: Double): Unit =
    if !(value >= 0) || value.isInfinite then
      throw IllegalArgumentException(s"angularDamping must be finite and at least 0, got $value")
    _angularDamping = value

  /** Current world position of the grabbed point. */
  def connection: Vector2D = point.position

  /** Impulse applied to the body in the current (or last) step, N s; at most maxForce times the step. */
  def impulse: Vector2D = Vector2D(impulseX, impulseY)

  /** Only node2, the dragged body, has to be in the world; node1 is the joint's own. */
  override private[sims] def bodiesIn(world: World): Boolean = node2.world eq world

  /** Starts a step: the step's impulse restarts at 0 (no force is applied here). */
  def applyForce(): Unit =
    impulseX = 0
    impulseY = 0
    stepStarting = true

  def correctVelocity(h: Double): Unit =
    val b = node2
    if b.invMass != 0 then // a fixed body cannot be dragged
      if stepStarting then
        b.w /= 1 + h * _angularDamping
        stepStarting = false
      point.update()
      val rx = point.armX
      val ry = point.armY
      val omega = 2 * math.Pi * _frequency
      val mass = b.mass
      val stiffness = mass * omega * omega
      val damping = 2 * mass * _dampingRatio * omega
      val softness = h * (damping + h * stiffness)
      val gamma = 1 / softness
      val betaOverH = stiffness / (damping + h * stiffness)
      val invI = b.invI
      val offDiagonal = -invI * rx * ry
      val k11 = b.invMass + invI * ry * ry + gamma
      val k22 = b.invMass + invI * rx * rx + gamma
      val cdotX = b.vx - b.w * ry
      val cdotY = b.vy + b.w * rx
      val rhsX = cdotX + betaOverH * (point.x - _target.x) + gamma * impulseX
      val rhsY = cdotY + betaOverH * (point.y - _target.y) + gamma * impulseY
      // (K + gamma E) dLambda = -rhs; K + gamma E is positive definite (gamma > 0).
      val determinant = k11 * k22 - offDiagonal * offDiagonal
      val oldX = impulseX
      val oldY = impulseY
      impulseX += (k22 * -rhsX - offDiagonal * -rhsY) / determinant
      impulseY += (k11 * -rhsY - offDiagonal * -rhsX) / determinant
      val maxImpulse = maxForce * h
      val size = math.sqrt(impulseX * impulseX + impulseY * impulseY)
      if size > maxImpulse then
        impulseX *= maxImpulse / size
        impulseY *= maxImpulse / size
      b.impulseAt(impulseX - oldX, impulseY - oldY, rx, ry)

  def correctPosition(h: Double): Unit = ()

  override def toString: String = s"MouseJoint($node2, target = $_target, maxForce = $maxForce)"
