package sims.dynamics.joints

import sims.dynamics.Body
import sims.geometry.Vector2D

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
  * (deviation 2 in docs/deviations.md).
  *
  * @param anchor the pin, world coordinates at creation; it then moves with both bodies
  */
final class RevoluteJoint(val node1: Body, val node2: Body, anchor: Vector2D) extends Joint:
  checkNodes()
  Vector2D.requireFinite("anchor", anchor)

  /** The pin's point on each body (the soft step reads them too). */
  private[sims] val attachment1 = Anchor(node1, anchor)
  private[sims] val attachment2 = Anchor(node2, anchor)
  // The classic step's arms of the pin's points.
  private val point1 = attachment1.arm()
  private val point2 = attachment2.arm()

  /** The anchors and placements this joint was made from (for saving a world). */
  private[sims] val origin: JointOrigin = JointOrigin(node1, anchor, node2, anchor)

  /** Relative rotation `node2.rotation - node1.rotation` at creation: `angle` is measured from it. */
  val referenceAngle: Double = node2.rotation - node1.rotation

  /** How far node2 has turned relative to node1 since the joint was made, rad (counter-clockwise). */
  def angle: Double = node2.angle - node1.angle - referenceAngle

  /** How fast node2 turns relative to node1, rad/s. */
  def angleSpeed: Double = node2.w - node1.w

  /** The range `angle` is kept in (default None: no limit). Under both steps: the classic step
    * corrects it one-sidedly after the pin, in velocity and in position.
    */
  var limits: Option[JointLimits] = None

  /** The motor that drives `angleSpeed` (default None). Needs the soft step. */
  var motor: Option[JointMotor] = None

  /** The spring that pulls `angle` back to 0 (default None). Needs the soft step. */
  var spring: Option[JointSpring] = None

  override private[sims] def softStepFeature: Option[String] =
    if motor.nonEmpty then Some("a motor") else if spring.nonEmpty then Some("a spring") else super.softStepFeature

  /** Current world position of the pin on node1. */
  def connection1: Vector2D = point1.position

  /** Current world position of the pin on node2. */
  def connection2: Vector2D = point2.position

  /** How far apart the pin's points on the two bodies are now (0 when the joint holds), m. */
  def separation: Double = (connection2 - connection1).length

  // The classic step's 2x2 system (see PinMatrix).
  private val matrix = PinMatrix()

  /** The pin's K for arms (a1x, a1y) to the pin points and (b1x, b1y) where the impulse acts
    * (see `PinMatrix.setUp`); returns its determinant.
    */
  private def effectiveMassMatrix(a1x: Double, a1y: Double, b1x: Double, b1y: Double,
      a2x: Double, a2y: Double, b2x: Double, b2y: Double): Double =
    matrix.setUp(node1.invMass, node1.invI, node2.invMass, node2.invI, a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y)

  def correctVelocity(h: Double): Unit =
    correctPinVelocity()
    if limits.nonEmpty then correctLimitVelocity(limits.get)

  private def correctPinVelocity(): Unit =
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
      matrix.solve(textbook, -cdotX, -cdotY)
      b1.impulseAt(-matrix.solutionX, -matrix.solutionY, point1.armX, point1.armY)
      b2.impulseAt(matrix.solutionX, matrix.solutionY, point2.armX, point2.armY)
    else
      matrix.solve(mixed, -cdotX, -cdotY)
      b1.impulseAt(-matrix.solutionX, -matrix.solutionY, m1x, m1y)
      b2.impulseAt(matrix.solutionX, matrix.solutionY, m2x, m2y)

  def correctPosition(h: Double): Unit =
    correctPin()
    if limits.nonEmpty then correctLimitPosition(limits.get)

  /** The limits' velocity correction (an extension of SiMS's joints): at or beyond an end, a
    * relative turn that would go further out is stopped, one-sidedly.
    */
  private def correctLimitVelocity(range: JointLimits): Unit =
    val inverse = node1.invI + node2.invI
    if inverse > 0 then
      val relative = node2.w - node1.w
      val a = angle
      val stop = if a <= range.lower && relative < 0 then -relative
      else if a >= range.upper && relative > 0 then -relative
      else 0.0
      if stop != 0 then
        node1.w -= stop / inverse * node1.invI
        node2.w += stop / inverse * node2.invI

  /** The limits' position correction: an angle beyond an end is turned back to it, both bodies
    * sharing the turn by their inverse inertias.
    */
  private def correctLimitPosition(range: JointLimits): Unit =
    val inverse = node1.invI + node2.invI
    if inverse > 0 then
      val a = angle
      val turn = if a < range.lower then range.lower - a else if a > range.upper then range.upper - a else 0.0
      if turn != 0 then
        node1.displace(0, 0, -turn / inverse * node1.invI)
        node2.displace(0, 0, turn / inverse * node2.invI)

  private def correctPin(): Unit =
    point1.update()
    point2.update()
    val b1 = node1
    val b2 = node2
    val cX = point2.x - point1.x
    val cY = point2.y - point1.y
    val determinant = effectiveMassMatrix(point1.armX, point1.armY, point1.armX, point1.armY,
      point2.armX, point2.armY, point2.armX, point2.armY)
    matrix.solve(determinant, -cX, -cY)
    // r x P for each body, with the arms taken before either body moves.
    val turn1 = point1.armX * matrix.solutionY - point1.armY * matrix.solutionX
    val turn2 = point2.armX * matrix.solutionY - point2.armY * matrix.solutionX
    b1.displace(-matrix.solutionX * b1.invMass, -matrix.solutionY * b1.invMass, -turn1 * b1.invI)
    b2.displace(matrix.solutionX * b2.invMass, matrix.solutionY * b2.invMass, turn2 * b2.invI)

  override def toString: String =
    val extras = limits.map(l => s", $l").getOrElse("") + motor.map(m => s", $m").getOrElse("") +
      spring.map(sp => s", $sp").getOrElse("")
    s"RevoluteJoint($node1, $node2, anchor = $anchor$extras)"
