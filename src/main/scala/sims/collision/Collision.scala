package sims.collision

import sims.dynamics.{Constraint, Edge, Shape}
import sims.geometry.Vector2D

/** A collision between two shapes: a constraint that keeps them from moving into each other
  * (documentation chapter 5). `shape1` is the reference shape, `shape2` the incident one; the
  * contact points lie on the reference shape's outline and the unit `normal` points away from
  * it. Velocity and position correction are implemented here, once, from those four fields.
  *
  * Derivation, per contact point p with r1 = p - pos1, r2 = p - pos2, n the normal:
  *   Cdot = n . (v2 + w2 x r2 - v1 - w1 x r1) (1 + e)  >= 0, corrected only when negative
  *   J M^-1 J^T = 1/m1 + (r1 x n)^2 / I1 + 1/m2 + (r2 x n)^2 / I2   (its inverse: m)
  *   lambda = -m Cdot: impulse n lambda on body 2, -n lambda on body 1
  *   friction along t = n.leftNormal: lambdaT = -mT (relative velocity . t), clamped to
  *   [-mu |lambda|, mu |lambda|]
  *   position: C = 0.01 - overlap along n, corrected only when C <= 0: P = -n m C
  * with e and mu the products of the shapes' restitutions and frictions.
  */
abstract class Collision extends Constraint:
  /** The reference shape. */
  def shape1: Shape

  /** The incident shape. */
  def shape2: Shape

  /** Contact points, world coordinates. */
  def points: Iterable[Vector2D]

  /** Unit contact normal, pointing away from `shape1`. */
  def normal: Vector2D

  // Hot-loop copy of the normal and the points as plain doubles, read by the corrections
  // without virtual calls. The built-in kinds write it whenever they are (re)computed; for
  // other kinds it is loaded once from `normal` and `points` on first use.
  private[sims] var normalX: Double = 0
  private[sims] var normalY: Double = 0
  /** Number of contact points, or -1 until the hot copy is loaded. */
  private[sims] var pointCount: Int = -1
  private[sims] var pointXs: Array[Double] = Collision.NoPoints
  private[sims] var pointYs: Array[Double] = Collision.NoPoints

  private[sims] final def pointX(i: Int): Double = { load(); pointXs(i) }
  private[sims] final def pointY(i: Int): Double = { load(); pointYs(i) }

  /** Loads the hot copy from `normal` and `points` unless a built-in kind wrote it. */
  private[sims] def load(): Unit =
    if pointCount < 0 then
      val n = normal
      normalX = n.x
      normalY = n.y
      val ps = points.toArray
      pointXs = ps.map(_.x)
      pointYs = ps.map(_.y)
      pointCount = ps.length

  /** Makes room for `n` points in the hot copy (built-in kinds; grows, never shrinks). */
  private[collision] final def ensureCapacity(n: Int): Unit =
    if pointXs.length < n then
      pointXs = new Array[Double](math.max(n, 2 * pointXs.length))
      pointYs = new Array[Double](pointXs.length)

  /** The hot copy's points as vectors (for the built-in kinds' `points`). */
  private[collision] final def pointVectors: IndexedSeq[Vector2D] =
    load()
    scala.collection.immutable.ArraySeq.tabulate(pointCount)(i => Vector2D(pointXs(i), pointYs(i)))

  /** True for the built-in kinds, whose points the world's contact solver reads directly
    * instead of calling `correctVelocity` (which they do not override).
    */
  private[sims] def solvedInPlace: Boolean = false

  def correctVelocity(h: Double): Unit =
    load()
    val b1 = shape1.body
    val b2 = shape2.body
    val nx = normalX
    val ny = normalY
    val tx = -ny
    val ty = nx
    val restitutionFactor = 1 + shape1.restitution * shape2.restitution
    val mu = shape1.friction * shape2.friction
    var i = 0
    while i < pointCount do
      val r1x = pointXs(i) - b1.x; val r1y = pointYs(i) - b1.y
      val r2x = pointXs(i) - b2.x; val r2y = pointYs(i) - b2.y
      Collision.correctVelocityAt(b1, b2, r1x, r1y, r2x, r2y, nx, ny, restitutionFactor, mu,
        Collision.effectiveMass(b1, b2, r1x, r1y, r2x, r2y, nx, ny),
        Collision.effectiveMass(b1, b2, r1x, r1y, r2x, r2y, tx, ty))
      i += 1

  def correctPosition(h: Double): Unit =
    load()
    val b1 = shape1.body
    val b2 = shape2.body
    val nx = normalX
    val ny = normalY
    var i = 0
    while i < pointCount do
      Collision.correctPositionAt(b1, b2, pointXs(i), pointYs(i), nx, ny, Collision.overlapAlong(shape1, shape2, nx, ny))
      i += 1

  override def toString: String =
    s"${getClass.getSimpleName}(normal = $normal, points = ${points.mkString(", ")})"

/** Constants and helpers of the contact constraint. */
object Collision:
  private val NoPoints = new Array[Double](0)

  /** Velocity correction at one contact point (arms r1, r2, normal n, restitution factor 1 + e,
    * friction mu, effective masses m along n and mT along t = n.leftNormal).
    */
  private[sims] inline def correctVelocityAt(b1: sims.dynamics.Body, b2: sims.dynamics.Body,
      r1x: Double, r1y: Double, r2x: Double, r2y: Double, nx: Double, ny: Double,
      restitutionFactor: Double, mu: Double, m: Double, mT: Double): Unit =
    // Normal part: an inequality constraint, corrected only when the points approach.
    val vn = relativeVelocity(b1, b2, r1x, r1y, r2x, r2y, nx, ny)
    val cDot = vn * restitutionFactor
    var lambda = 0.0
    if cDot <= 0 then
      lambda = -m * cDot
      b1.impulseAt(-nx * lambda, -ny * lambda, r1x, r1y)
      b2.impulseAt(nx * lambda, ny * lambda, r2x, r2y)
    // Friction along the tangent, bounded by mu times this correction's normal impulse.
    val tx = -ny
    val ty = nx
    val vt = relativeVelocity(b1, b2, r1x, r1y, r2x, r2y, tx, ty)
    val bound = mu * math.abs(lambda)
    val lambdaT = math.max(-bound, math.min(bound, -mT * vt))
    b1.impulseAt(-tx * lambdaT, -ty * lambdaT, r1x, r1y)
    b2.impulseAt(tx * lambdaT, ty * lambdaT, r2x, r2y)

  /** (v2(p) - v1(p)) . (dx, dy) for the point at arms r1, r2. */
  private inline def relativeVelocity(b1: sims.dynamics.Body, b2: sims.dynamics.Body,
      r1x: Double, r1y: Double, r2x: Double, r2y: Double, dx: Double, dy: Double): Double =
    val vx = (b2.vx - b2.w * r2y) - (b1.vx - b1.w * r1y)
    val vy = (b2.vy + b2.w * r2x) - (b1.vy + b1.w * r1x)
    vx * dx + vy * dy

  /** Position correction at one contact point p = (px, py), with the shapes' current `overlap`
    * along the normal n: C = 0.01 - overlap, corrected only when C <= 0, by P = -n m C.
    */
  private[sims] inline def correctPositionAt(b1: sims.dynamics.Body, b2: sims.dynamics.Body, px: Double, py: Double,
      nx: Double, ny: Double, overlap: Double): Unit =
    val c = sims.Defaults.ToleratedOverlap - overlap
    if c <= 0 then
      val r1x = px - b1.x; val r1y = py - b1.y
      val r2x = px - b2.x; val r2y = py - b2.y
      val m = effectiveMass(b1, b2, r1x, r1y, r2x, r2y, nx, ny)
      val impulseX = -nx * m * c
      val impulseY = -ny * m * c
      b1.displace(-impulseX * b1.invMass, -impulseY * b1.invMass, -(r1x * impulseY - r1y * impulseX) * b1.invI)
      b2.displace(impulseX * b2.invMass, impulseY * b2.invMass, (r2x * impulseY - r2y * impulseX) * b2.invI)

  /** 1 / (1/m1 + (r1 x d)^2/I1 + 1/m2 + (r2 x d)^2/I2), 0 when both bodies are fixed. */
  private[sims] inline def effectiveMass(b1: sims.dynamics.Body, b2: sims.dynamics.Body,
      r1x: Double, r1y: Double, r2x: Double, r2y: Double, dx: Double, dy: Double): Double =
    val cr1 = r1x * dy - r1y * dx
    val cr2 = r2x * dy - r2y * dx
    val invMass = b1.invMass + cr1 * cr1 * b1.invI + b2.invMass + cr2 * cr2 * b2.invI
    if invMass == 0.0 then 0.0 else 1 / invMass

  /** Overlap of the two shapes' projections onto the unit axis (nx, ny), which points from s1
    * towards s2. An edge has no inside, so its projection has no length and would overlap
    * nothing: it counts as solid on its far side from the other shape (behind it along the
    * axis as s1, beyond it as s2), so that the overlap is how far the other shape reaches
    * through it.
    */
  private[sims] def overlapAlong(s1: Shape, s2: Shape, nx: Double, ny: Double): Double =
    val lower1 = if s1.isInstanceOf[Edge] then Double.NegativeInfinity else s1.projectMin(nx, ny)
    val upper1 = s1.projectMax(nx, ny)
    val lower2 = s2.projectMin(nx, ny)
    val upper2 = if s2.isInstanceOf[Edge] then Double.PositiveInfinity else s2.projectMax(nx, ny)
    sims.geometry.Projection.overlap(lower1, upper1, lower2, upper2)
