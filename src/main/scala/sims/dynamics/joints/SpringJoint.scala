package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

/** A spring between two anchor points, one on each body: a [[ForceJoint]] with Hooke's force
  * `springConstant * (|x| - initialLength)` along x = connection2 - connection1, pulling the
  * points together when stretched, plus a damping force `damping * (relative velocity projected
  * on x)` against the relative motion. Both forces act equal and opposite on the two bodies at
  * the connection points (the original applied the damping with the same sign to both; see the
  * deviations). No velocity or position correction.
  */
final class SpringJoint(val node1: Body, anchor1: Vector2D, val node2: Body, anchor2: Vector2D,
    val springConstant: Double, val initialLength: Double) extends Joint with ForceJoint:
  checkNodes()
  Vector2D.requireFinite("anchor1", anchor1)
  Vector2D.requireFinite("anchor2", anchor2)
  if !(springConstant >= 0) || springConstant.isInfinite then
    throw IllegalArgumentException(s"springConstant must be finite and at least 0, got $springConstant")
  if !(initialLength >= 0) || initialLength.isInfinite then
    throw IllegalArgumentException(s"initialLength must be finite and at least 0, got $initialLength")

  /** A spring between two anchors whose rest length is their distance at creation. */
  def this(node1: Body, anchor1: Vector2D, node2: Body, anchor2: Vector2D, springConstant: Double) =
    this(node1, anchor1, node2, anchor2, springConstant, (anchor2 - anchor1).length)

  /** A spring between the two centres of mass, rest length their distance at creation. */
  def this(node1: Body, node2: Body, springConstant: Double) =
    this(node1, node1.pos, node2, node2.pos, springConstant)

  private val a1 = Anchor(node1, anchor1).arm()
  private val a2 = Anchor(node2, anchor2).arm()

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor1, node2, anchor2)
  private var _damping = 0.0

  /** Damping coefficient in N s/m (default 0). */
  def damping: Double = _damping

  /** Sets the damping; must be finite and at least 0. */
  def damping_=(value: Double): Unit =
    if !(value >= 0) || value.isInfinite then
      throw IllegalArgumentException(s"damping must be finite and at least 0, got $value")
    _damping = value

  /** Current world position of the anchor on node1. */
  def connection1: Vector2D = a1.position

  /** Current world position of the anchor on node2. */
  def connection2: Vector2D = a2.position

  /** Force on node1 (node2 gets its opposite): spring plus damping. */
  def force: Vector2D =
    measureForce()
    Vector2D(forceX, forceY)

  def applyForce(): Unit =
    measureForce()
    node1.forceAt(forceX, forceY, a1.armX, a1.armY)
    node2.forceAt(-forceX, -forceY, a2.armX, a2.armY)

  // The force on node1, set by `measureForce`.
  private var forceX, forceY = 0.0

  /** Sets (forceX, forceY) to the force on node1 at the current placements and velocities: with
    * x = c2 - c1 from the anchor on node1 to that on node2 and v the velocity of c2 relative to
    * c1, k (|x| - L) x / |x| + c (v . x / x . x) x. In scalars, allocating nothing (the soft step
    * asks on every substep), except where |x|^2 is 0 or over- or underflows: there `Vector2D`'s
    * rules for the null vector, `unit`, `length` and `project` decide, on the same operations.
    */
  private def measureForce(): Unit =
    a1.update()
    a2.update()
    val dx = a2.x - a1.x
    val dy = a2.y - a1.y
    val squared = dx * dx + dy * dy
    val relativeX = (node2.vx - node2.w * (a2.y - node2.y)) - (node1.vx - node1.w * (a1.y - node1.y))
    val relativeY = (node2.vy + node2.w * (a2.x - node2.x)) - (node1.vy + node1.w * (a1.x - node1.x))
    if Vector2D.safeSquare(squared) then
      val length = math.sqrt(squared)
      val stretch = springConstant * (length - initialLength)
      val along = (relativeX * dx + relativeY * dy) / squared
      forceX = dx / length * stretch + dx * along * _damping
      forceY = dy / length * stretch + dy * along * _damping
    else
      val x = Vector2D(dx, dy)
      val spring = if x.isNull then Vector2D.Null else x.unit * (springConstant * (x.length - initialLength))
      val f = spring + Vector2D(relativeX, relativeY).project(x) * _damping
      forceX = f.x
      forceY = f.y

  /** The stability number of this spring integrated explicitly over steps of `h` seconds:
    * (k h^2 + 2 c h) / m, with 1/m = 1/m1 + 1/m2 + r1^2/I1 + r2^2/I2 (r the anchors' arms; an
    * upper bound of the inverse mass along any direction). The step integrates velocities
    * before positions (symplectic Euler); for a spring between two masses it is stable exactly
    * when this number is below 4 (k h^2 / m < 4 undamped: omega h < 2).
    */
  private[sims] def stabilityNumber(h: Double): Double =
    a1.update()
    a2.update()
    val inverseMass = node1.invMass + node2.invMass +
      node1.invI *
      (a1.armX * a1.armX + a1.armY * a1.armY) +
      node2.invI *
      (a2.armX * a2.armX + a2.armY * a2.armY)
    (springConstant * h * h + 2 * _damping * h) * inverseMass

  /** A spring too stiff for the solver's force interval grows without bound, to 1e150 m and
    * beyond before any value overflows, so the state a failed step would restore is ruined
    * already: it is refused instead.
    */
  override private[sims] def forceIntervalProblem(h: Double, solver: AnyRef): Option[String] =
    val number = stabilityNumber(h)
    if number < SpringJoint.StabilityLimit then None
    else
      Some(s"$this is too stiff for the time step: (k h^2 + 2 c h) / m = $number with " +
        s"h = $h s (${sims.dynamics.StepGuard.solverName(solver)}'s force interval) and c = $damping N s/m; " +
        s"springs integrated explicitly diverge from ${SpringJoint.StabilityLimit} on. Lower springConstant or " +
        "damping, make the bodies heavier or shorten the time step (or, with SoftStep, use more substeps)")

  def correctVelocity(h: Double): Unit = ()

  def correctPosition(h: Double): Unit = ()

  override def toString: String =
    s"SpringJoint($node1, $node2, springConstant = $springConstant, initialLength = $initialLength)"

/** The spring's stability limit. */
object SpringJoint:
  /** Springs whose stability number (k h^2 + 2 c h) / m reaches this diverge when their forces
    * are integrated explicitly over steps of h.
    */
  val StabilityLimit: Double = 4.0
