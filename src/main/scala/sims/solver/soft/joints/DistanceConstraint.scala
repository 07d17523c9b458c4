package sims.solver.soft.joints

import sims.dynamics.joints.DistanceJoint
import sims.solver.soft.{SoftBodies, SoftContext}
import sims.solver.soft.SoftBodies.*

/** The distance joint under the soft step: the classic C, J and K (see [[DistanceJoint]]),
  *   C = |x| - distance,  Cdot = u . (v2 + w2 x r2 - v1 - w1 x r1),
  *   K = 1/m1 + (r1 x u)^2 / I1 + 1/m2 + (r2 x u)^2 / I2,
  * solved as a soft constraint on the substeps' velocities (solve pass:
  * lambda = -massScale K^-1 (Cdot + biasRate C) - impulseScale lambdaAcc; relax pass: the rigid
  * lambda = -K^-1 Cdot). The arms are taken at the start of the step and turned by each body's
  * rotation since; u and C come from the bodies' displacements; K stays as prepared.
  */
private[sims] final class DistanceConstraint(distanceJoint: DistanceJoint) extends JointConstraint(distanceJoint, 1):
  private val arm1 = distanceJoint.attachment1.arm()
  private val arm2 = distanceJoint.attachment2.arm()
  private val ends = SoftAnchors()
  private var axialMass = 0.0
  // Current geometry, set by `measure`.
  private var axisX, axisY, length = 0.0

  def prepare(context: SoftContext): Unit =
    val bodies = context.bodies
    arm1.update()
    arm2.update()
    ends.start(bodies, distanceJoint.node1.index, distanceJoint.node2.index, arm1.armX, arm1.armY, arm2.armX, arm2.armY)
    // A joint tree takes its rows from `rowsAt`: the axial mass is `solve`'s alone.
    if !inTree then prepareAxialMass(bodies)

  private def prepareAxialMass(bodies: SoftBodies): Unit =
    measure(bodies)
    val cr1 = ends.arm1X * axisY - ends.arm1Y * axisX
    val cr2 = ends.arm2X * axisY - ends.arm2Y * axisX
    val i1 = ends.index1
    val i2 = ends.index2
    val k = bodies.invMass(i1) + bodies.invI(i1) * cr1 * cr1 + bodies.invMass(i2) + bodies.invI(i2) * cr2 * cr2
    axialMass = if k > 0 then 1 / k else 0

  /** The current arms, axis u and length |x| from the bodies' motion since the step began. */
  private def measure(bodies: SoftBodies): Unit =
    ends.measure(bodies.state)
    length = aim(ends.centresX + ends.arm2X - ends.arm1X, ends.centresY + ends.arm2Y - ends.arm1Y)

  /** Sets the axis along (dx, dy), kept as it was where the ends meet; returns the length. */
  private inline def aim(dx: Double, dy: Double): Double =
    val length = math.sqrt(dx * dx + dy * dy)
    if length > 0 then
      axisX = dx / length
      axisY = dy / length
    length

  override def directRows: Int = 1

  override def rowsAt(context: SoftContext, rows: JointRows): Unit =
    // `measure`'s arithmetic in locals, into the rows: of the fields, only the axis (for
    // `report`, and kept where the ends meet) is written (in JavaScript, a Double field is a
    // box of its own, and a write to one costs more than a write to an array).
    val state = context.bodies.state
    val s1 = ends.index1 * Stride
    val s2 = ends.index2 * Stride
    val arm1X = ends.turnedArm1X(state, s1); val arm1Y = ends.turnedArm1Y(state, s1)
    val arm2X = ends.turnedArm2X(state, s2); val arm2Y = ends.turnedArm2Y(state, s2)
    val length = aim(ends.currentCentresX(state, s1, s2) + arm2X - arm1X, ends.currentCentresY(state, s1, s2) + arm2Y - arm1Y)
    val ux = axisX
    val uy = axisY
    rows.count = 1
    rows.set(0, -ux, -uy, -(arm1X * uy - arm1Y * ux), ux, uy, arm2X * uy - arm2Y * ux, length - distanceJoint.distance)

  def warmStart(context: SoftContext): Unit =
    val bodies = context.bodies
    measure(bodies)
    apply(bodies, impulse(0))

  def solve(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    measure(bodies)
    val state = bodies.state
    val s1 = ends.index1 * Stride
    val s2 = ends.index2 * Stride
    val vx = (state(s2 + VelocityX) - state(s2 + AngularVelocity) * ends.arm2Y) -
      (state(s1 + VelocityX) - state(s1 + AngularVelocity) * ends.arm1Y)
    val vy = (state(s2 + VelocityY) + state(s2 + AngularVelocity) * ends.arm2X) -
      (state(s1 + VelocityY) + state(s1 + AngularVelocity) * ends.arm1X)
    val cdot = axisX * vx + axisY * vy
    val softness = context.jointSoftness
    val lambda =
      if useBias then
        val c = length - distanceJoint.distance
        -softness.massScale * axialMass * (cdot + softness.biasRate * c) - softness.impulseScale * impulse(0)
      else -axialMass * cdot
    impulse(0) += lambda
    apply(bodies, lambda)

  /** Applies the impulse `lambda` along the axis: -u to body 1, +u to body 2, at their points. */
  override def report(inverseH: Double): Unit =
    distanceJoint.reactionX = axisX * impulse(0) * inverseH
    distanceJoint.reactionY = axisY * impulse(0) * inverseH

  private def apply(bodies: SoftBodies, lambda: Double): Unit =
    val px = axisX * lambda
    val py = axisY * lambda
    bodies.applyImpulse(ends.index1, -px, -py, ends.arm1X, ends.arm1Y)
    bodies.applyImpulse(ends.index2, px, py, ends.arm2X, ends.arm2Y)
