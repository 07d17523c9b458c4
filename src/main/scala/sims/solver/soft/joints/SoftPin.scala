package sims.solver.soft.joints

import sims.dynamics.joints.{AnchorArm, PinMatrix}
import sims.solver.soft.{SoftBodies, SoftContext, Softness}
import sims.solver.soft.SoftBodies.*

/** The point constraint that pins two bodies together, as the soft step solves it (the
  * revolute joint's, and the weld joint's linear part):
  *   C = p2 - p1 (the pin's points: their arms at the start of the step turned by each body's
  *       rotation since),
  *   Cdot = v2 + w2 x r2 - v1 - w1 x r1, K = (1/m1 + 1/m2) E + the arms' terms (2 x 2),
  * with Cdot, K and the impulses taken at the middle of p1 and p2, solved as a soft constraint:
  * lambda = -massScale K^-1 (Cdot + biasRate C) - impulseScale lambdaAcc (relax pass: the rigid
  * lambda = -K^-1 Cdot). Impulses at two points an open pin apart would form a couple and change
  * the angular momentum (measured 0.4% over two seconds in a free pair); at the middle they do not.
  * Its two impulses are the owner's `impulse(0)` and `impulse(1)`.
  */
private[sims] final class SoftPin(point1: AnchorArm, point2: AnchorArm):
  private val pin = SoftAnchors()
  private val matrix = PinMatrix()
  // Set by `measure`: the pin's error C = p2 - p1, and the arms from each centre to the middle
  // of p1 and p2, where both impulses act.
  private var errorX, errorY = 0.0
  /** The arms from each centre to the middle of the pin's points (set by `measure`). */
  var arm1X, arm1Y, arm2X, arm2Y = 0.0

  /** Body 1's and body 2's index in the step's arrays. */
  def index1: Int = pin.index1
  def index2: Int = pin.index2

  /** Takes the arms at the start of the step, for the bodies of indices `index1` and `index2`. */
  def prepare(bodies: SoftBodies, index1: Int, index2: Int): Unit =
    point1.update()
    point2.update()
    pin.start(bodies, index1, index2, point1.armX, point1.armY, point2.armX, point2.armY)

  /** Sets the error and the arms from the bodies' motion since the step began. */
  def measure(state: Array[Double]): Unit =
    pin.measure(state)
    errorX = pin.centresX + pin.arm2X - pin.arm1X
    errorY = pin.centresY + pin.arm2Y - pin.arm1Y
    // The middle is p1 + C / 2 from body 1's centre, p2 - C / 2 from body 2's.
    arm1X = pin.arm1X + 0.5 * errorX; arm1Y = pin.arm1Y + 0.5 * errorY
    arm2X = pin.arm2X - 0.5 * errorX; arm2Y = pin.arm2Y - 0.5 * errorY

  /** The two rows for the direct solver, at the current substep. */
  def rowsAt(context: SoftContext, rows: JointRows): Unit =
    measure(context.bodies.state)
    rows.count = 2
    rows.set(0, -1, 0, arm1Y, 1, 0, -arm2Y, errorX)
    rows.set(1, 0, -1, -arm1X, 0, 1, arm2X, errorY)

  /** Applies the accumulated impulse (impulse(0), impulse(1)) on body 2, its opposite on body 1. */
  def warmStart(context: SoftContext, impulse: Array[Double]): Unit =
    val bodies = context.bodies
    measure(bodies.state)
    bodies.applyImpulse(pin.index1, -impulse(0), -impulse(1), arm1X, arm1Y)
    bodies.applyImpulse(pin.index2, impulse(0), impulse(1), arm2X, arm2Y)

  /** One pass: with the joints' softness and bias (`useBias`) or rigid without; a pin of its
    * own stiffness (`own` not null, a soft weld) is soft with it in both passes.
    */
  def solve(context: SoftContext, useBias: Boolean, impulse: Array[Double], own: Softness = null): Unit =
    val bodies = context.bodies
    val state = bodies.state
    measure(state)
    val s1 = pin.index1 * Stride
    val s2 = pin.index2 * Stride
    val cdotX = state(s2 + VelocityX) - state(s2 + AngularVelocity) * arm2Y - state(s1 + VelocityX) +
      state(s1 + AngularVelocity) * arm1Y
    val cdotY = state(s2 + VelocityY) + state(s2 + AngularVelocity) * arm2X - state(s1 + VelocityY) -
      state(s1 + AngularVelocity) * arm1X
    var rightX = cdotX
    var rightY = cdotY
    var massScale = 1.0
    var impulseScale = 0.0
    if useBias || own != null then
      val softness = if own != null then own else context.jointSoftness
      rightX += softness.biasRate * errorX
      rightY += softness.biasRate * errorY
      massScale = softness.massScale
      impulseScale = softness.impulseScale
    val i1 = pin.index1
    val i2 = pin.index2
    val determinant = matrix.setUp(bodies.invMass(i1), bodies.invI(i1), bodies.invMass(i2), bodies.invI(i2),
      arm1X, arm1Y, arm1X, arm1Y, arm2X, arm2Y, arm2X, arm2Y)
    matrix.solve(determinant, rightX, rightY)
    val impulseX = -massScale * matrix.solutionX - impulseScale * impulse(0)
    val impulseY = -massScale * matrix.solutionY - impulseScale * impulse(1)
    impulse(0) += impulseX
    impulse(1) += impulseY
    bodies.applyImpulse(pin.index1, -impulseX, -impulseY, arm1X, arm1Y)
    bodies.applyImpulse(pin.index2, impulseX, impulseY, arm2X, arm2Y)
