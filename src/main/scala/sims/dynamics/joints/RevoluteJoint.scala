package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D
import sims.solver.soft.{JointRows, SoftAnchors, SoftBodies, SoftContext}
import sims.solver.soft.SoftBodies.*

/** Pins two bodies together at one point; they may turn freely about it (a hinge).
  *
  * Derivation, with p1 = x1 + r1 and p2 = x2 + r2 the pin's points on each body (both at
  * `anchor` when the joint is made) and `w x r = w (-r.y, r.x)`:
  *   C     = p2 - p1                                          (two components)
  *   Cdot  = v2 + w2 x r2 - v1 - w1 x r1
  *   J     = [-E, -(r1.leftNormal), E, r2.leftNormal]         (E the 2x2 identity)
  *   K = J M^-1 J^T = (1/m1 + 1/m2) E
  *                    + 1/I1 [r1.y^2, -r1.x r1.y; -r1.x r1.y, r1.x^2]
  *                    + 1/I2 [r2.y^2, -r2.x r2.y; -r2.x r2.y, r2.x^2]
  * Velocity: solve K P = -Cdot; impulse P on body 2 and -P on body 1. Both act at the middle of
  * p1 and p2 (not each at its own point): with the pin open by C, impulses at p1 and p2 would
  * form a couple C x P and change the angular momentum. K is then taken with the arms to that
  * middle on one side (see `correctVelocity`); it is the K above whenever C = 0.
  * Position: solve K P = -C; body 1 moves by -P/m1 and turns by -(r1 x P)/I1, body 2 moves by
  * +P/m2 and turns by +(r2 x P)/I2 (velocities unchanged), as the DistanceJoint does.
  * A fixed body has 1/m = 1/I = 0; K is singular only when both bodies are fixed, and then
  * nothing is corrected. The original SiMS had a wrong K and no position correction
  * (deviation 2 of the SPEC).
  *
  * @param anchor the pin, world coordinates at creation; it then moves with both bodies
  */
final class RevoluteJoint(val node1: Body, val node2: Body, anchor: Vector2D) extends Joint:
  checkNodes()
  Vector2D.requireFinite("anchor", anchor)

  private val point1 = Anchor(node1, anchor)
  private val point2 = Anchor(node2, anchor)

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor, node2, anchor)

  /** Current world position of the pin on node1. */
  def connection1: Vector2D = point1.position

  /** Current world position of the pin on node2. */
  def connection2: Vector2D = point2.position

  /** How far apart the pin's points on the two bodies are now (0 when the joint holds), m. */
  def separation: Double = (connection2 - connection1).length

  // The last 2x2 system set up by `effectiveMassMatrix` (row by row) and the solution of the
  // last `solve`: fields rather than objects, so the iterations allocate nothing.
  private var k11, k12, k21, k22 = 0.0
  private var solutionX, solutionY = 0.0

  /** Sets (k11 k12; k21 k22) to the change of the pin points' relative velocity per unit
    * impulse, when the impulse acts at arms (b1x, b1y), (b2x, b2y) and the pin points are at
    * arms (a1x, a1y), (a2x, a2y):
    * (1/m1 + 1/m2) E + sum over both bodies of 1/I [a.y b.y, -a.y b.x; -a.x b.y, a.x b.x].
    * With a = b this is the symmetric K of the derivation. Returns its determinant.
    */
  private def effectiveMassMatrix(a1x: Double, a1y: Double, b1x: Double, b1y: Double,
      a2x: Double, a2y: Double, b2x: Double, b2y: Double): Double =
    val invMass = node1.invMass + node2.invMass
    val invI1 = node1.invI
    val invI2 = node2.invI
    k11 = invMass + invI1 * a1y * b1y + invI2 * a2y * b2y
    k12 = -invI1 * a1y * b1x - invI2 * a2y * b2x
    k21 = -invI1 * a1x * b1y - invI2 * a2x * b2y
    k22 = invMass + invI1 * a1x * b1x + invI2 * a2x * b2x
    k11 * k22 - k12 * k21

  /** Solves K P = (bx, by) for the matrix last set up, with its determinant; P = 0 when K is
    * singular (both bodies fixed).
    */
  private def solve(determinant: Double, bx: Double, by: Double): Unit =
    if determinant == 0 then
      solutionX = 0; solutionY = 0
    else
      solutionX = (k22 * bx - k12 * by) / determinant
      solutionY = (k11 * by - k21 * bx) / determinant

  def correctVelocity(h: Double): Unit =
    point1.update()
    point2.update()
    val b1 = node1
    val b2 = node2
    // Relative velocity of the two pin points: v + w x r for each body.
    val cdotX = b2.vx - b2.w * point2.armY - b1.vx + b1.w * point1.armY
    val cdotY = b2.vy + b2.w * point2.armX - b1.vy - b1.w * point1.armX
    // Both impulses act at one point, the middle of the two pin points, so that they form no
    // couple: angular momentum is then conserved exactly even while the pin is open (position
    // correction off). The impulse is chosen so that the pin points' relative velocity becomes 0,
    // as in the textbook constraint; its matrix is the textbook K when the pin is closed. When the
    // pin is wide open (a joint torn apart by contacts), that matrix can approach singularity and
    // give huge impulses; then the textbook impulses at the pin points are used instead.
    val middleX = 0.5 * (point1.x + point2.x)
    val middleY = 0.5 * (point1.y + point2.y)
    val m1x = middleX - b1.x
    val m1y = middleY - b1.y
    val m2x = middleX - b2.x
    val m2y = middleY - b2.y
    val textbook = effectiveMassMatrix(point1.armX, point1.armY, point1.armX, point1.armY,
      point2.armX, point2.armY, point2.armX, point2.armY)
    val mixed = effectiveMassMatrix(point1.armX, point1.armY, m1x, m1y, point2.armX, point2.armY, m2x, m2y)
    if !(mixed >= 0.5 * textbook) then
      // The matrix fields hold the mixed matrix now: set up the textbook one again.
      effectiveMassMatrix(point1.armX, point1.armY, point1.armX, point1.armY,
        point2.armX, point2.armY, point2.armX, point2.armY)
      solve(textbook, -cdotX, -cdotY)
      b1.impulseAt(-solutionX, -solutionY, point1.armX, point1.armY)
      b2.impulseAt(solutionX, solutionY, point2.armX, point2.armY)
    else
      solve(mixed, -cdotX, -cdotY)
      b1.impulseAt(-solutionX, -solutionY, m1x, m1y)
      b2.impulseAt(solutionX, solutionY, m2x, m2y)

  def correctPosition(h: Double): Unit =
    point1.update()
    point2.update()
    val b1 = node1
    val b2 = node2
    val cX = point2.x - point1.x
    val cY = point2.y - point1.y
    val determinant = effectiveMassMatrix(point1.armX, point1.armY, point1.armX, point1.armY,
      point2.armX, point2.armY, point2.armX, point2.armY)
    solve(determinant, -cX, -cY)
    // r x P for each body, with the arms taken before either body moves.
    val turn1 = point1.armX * solutionY - point1.armY * solutionX
    val turn2 = point2.armX * solutionY - point2.armY * solutionX
    b1.displace(-solutionX * b1.invMass, -solutionY * b1.invMass, -turn1 * b1.invI)
    b2.displace(solutionX * b2.invMass, solutionY * b2.invMass, turn2 * b2.invI)

  // ---- Soft step: the point constraint C = p2 - p1 (the pin's points: their arms at the start
  // of the step turned by each body's rotation since), with Cdot and the impulses at the middle
  // of p1 and p2 and K for those arms, solved as a soft constraint (SOFTSTEP.md section 3):
  // lambda = -massScale K^-1 (Cdot + biasRate C) - impulseScale lambdaAcc.

  private val accumulated = new Array[Double](2)
  private val pin = SoftAnchors()
  // Set by `armsSoft`: the pin's error C = p2 - p1, and the arms from each centre to the middle
  // of p1 and p2, where both impulses act (as in the classic step: impulses at two points an
  // open pin apart would form a couple and change the angular momentum; measured 0.4% over
  // two seconds in a free pair before this).
  private var errorX, errorY, arm1X, arm1Y, arm2X, arm2Y = 0.0

  override private[sims] def softImpulse: Array[Double] = accumulated

  override private[sims] def prepareSoft(context: SoftContext): Unit =
    point1.update()
    point2.update()
    pin.start(context.bodies, node1.index, node2.index, point1.armX, point1.armY, point2.armX, point2.armY)

  private def armsSoft(state: Array[Double]): Unit =
    pin.measure(state)
    errorX = pin.centresX + pin.arm2X - pin.arm1X
    errorY = pin.centresY + pin.arm2Y - pin.arm1Y
    // The middle is p1 + C / 2 from body 1's centre, p2 - C / 2 from body 2's.
    arm1X = pin.arm1X + 0.5 * errorX; arm1Y = pin.arm1Y + 0.5 * errorY
    arm2X = pin.arm2X - 0.5 * errorX; arm2Y = pin.arm2Y - 0.5 * errorY

  override private[sims] def directRows: Int = 2

  override private[sims] def rowsSoft(context: SoftContext, rows: JointRows): Unit =
    armsSoft(context.bodies.state)
    rows.count = 2
    rows.set(0, -1, 0, arm1Y, 1, 0, -arm2Y, errorX)
    rows.set(1, 0, -1, -arm1X, 0, 1, arm2X, errorY)

  override private[sims] def warmStartSoft(context: SoftContext): Unit =
    val bodies = context.bodies
    armsSoft(bodies.state)
    bodies.applyImpulse(pin.index1, -accumulated(0), -accumulated(1), arm1X, arm1Y)
    bodies.applyImpulse(pin.index2, accumulated(0), accumulated(1), arm2X, arm2Y)

  override private[sims] def solveSoft(context: SoftContext, useBias: Boolean): Unit =
    val bodies = context.bodies
    val state = bodies.state
    armsSoft(state)
    val s1 = pin.index1 * SoftBodies.Stride
    val s2 = pin.index2 * SoftBodies.Stride
    val cdotX = state(s2 + VelocityX) - state(s2 + AngularVelocity) * arm2Y - state(s1 + VelocityX) + state(s1 + AngularVelocity) * arm1Y
    val cdotY = state(s2 + VelocityY) + state(s2 + AngularVelocity) * arm2X - state(s1 + VelocityY) - state(s1 + AngularVelocity) * arm1X
    var rightX = cdotX
    var rightY = cdotY
    var massScale = 1.0
    var impulseScale = 0.0
    if useBias then
      val softness = context.jointSoftness
      rightX += softness.biasRate * errorX
      rightY += softness.biasRate * errorY
      massScale = softness.massScale
      impulseScale = softness.impulseScale
    val determinant = effectiveMassMatrix(arm1X, arm1Y, arm1X, arm1Y, arm2X, arm2Y, arm2X, arm2Y)
    solve(determinant, rightX, rightY)
    val impulseX = -massScale * solutionX - impulseScale * accumulated(0)
    val impulseY = -massScale * solutionY - impulseScale * accumulated(1)
    accumulated(0) += impulseX
    accumulated(1) += impulseY
    bodies.applyImpulse(pin.index1, -impulseX, -impulseY, arm1X, arm1Y)
    bodies.applyImpulse(pin.index2, impulseX, impulseY, arm2X, arm2Y)

  override def toString: String = s"RevoluteJoint($node1, $node2, anchor = $anchor)"
