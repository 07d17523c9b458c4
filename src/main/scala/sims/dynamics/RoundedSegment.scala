package sims.dynamics

import sims.geometry.{AABB, PortableMath, Projection, RayMath, Segment, Vector2D}

/** A shape made of the points within `radius` of a straight segment, its core: the segment of
  * length 2 `halfLength` through the shape's centre along its rotation (at rotation 0 from
  * (-halfLength, 0) to (halfLength, 0)). Either a [[Capsule]] (radius > 0) or an [[Edge]]
  * (radius 0); the narrowphase treats both as one kind, a segment with a radius.
  */
abstract class RoundedSegment private[sims] () extends Shape:
  /** Half the length of the core segment, m. */
  def halfLength: Double

  /** Distance of the outline from the core, m (0 for an edge). */
  def radius: Double

  // World ends of the core and the two side normals (right of vertex1 -> vertex2, then its
  // opposite, as the sides of a two-vertex polygon), recomputed lazily after a move.
  private val endXs = new Array[Double](2)
  private val endYs = new Array[Double](2)
  private val normalXs = new Array[Double](2)
  private val normalYs = new Array[Double](2)
  private var current = false

  override protected def moved(): Unit = current = false

  override private[sims] def refreshCaches(): Unit = refresh()

  override private[sims] def refreshBounds(): Unit = refresh()

  private def refresh(): Unit =
    if !current then
      val ux = PortableMath.cos(angle)
      val uy = PortableMath.sin(angle)
      endXs(0) = x - halfLength * ux; endYs(0) = y - halfLength * uy
      endXs(1) = x + halfLength * ux; endYs(1) = y + halfLength * uy
      // 0.0 - u rather than -u: no negative zeros in printed normals.
      normalXs(0) = uy; normalYs(0) = 0.0 - ux
      normalXs(1) = 0.0 - uy; normalYs(1) = ux
      current = true

  /** First end of the core segment, world coordinates. */
  def vertex1: Vector2D = { refresh(); Vector2D(endXs(0), endYs(0)) }

  /** Second end of the core segment, world coordinates. */
  def vertex2: Vector2D = { refresh(); Vector2D(endXs(1), endYs(1)) }

  /** The core segment, world coordinates. */
  def core: Segment = Segment(vertex1, vertex2)

  /** x of the core's two ends, for the narrowphase (not to be modified; valid until it moves). */
  private[sims] def coreXs: Array[Double] = { refresh(); endXs }
  /** y of the core's two ends. */
  private[sims] def coreYs: Array[Double] = { refresh(); endYs }
  /** x of the core's two side normals: right of vertex1 -> vertex2, then left. */
  private[sims] def coreNormalXs: Array[Double] = { refresh(); normalXs }
  /** y of the core's two side normals. */
  private[sims] def coreNormalYs: Array[Double] = { refresh(); normalYs }

  def AABB: AABB = new sims.geometry.AABB(Vector2D(minX, minY), Vector2D(maxX, maxY))

  /** The interval covered on `axis` (in units of its length): the core's ends projected, widened
    * by the radius.
    */
  def project(axis: Vector2D): Projection =
    val widen = radius * axis.length
    refresh()
    val p1 = endXs(0) * axis.x + endYs(0) * axis.y
    val p2 = endXs(1) * axis.x + endYs(1) * axis.y
    Projection(axis, math.min(p1, p2) - widen, math.max(p1, p2) + widen)

  /** True if `point` is within the radius of the core (on the core, for an edge). */
  def contains(point: Vector2D): Boolean =
    refresh()
    Segment.distance(endXs(0), endYs(0), endXs(1), endYs(1), point.x, point.y) <= radius

  override private[sims] def castRay(x1: Double, y1: Double, dx: Double, dy: Double, maxFraction: Double,
      hit: RayMath.Hit): Boolean =
    refresh()
    RayMath.capsule(endXs(0), endYs(0), endXs(1), endYs(1), radius, x1, y1, dx, dy, maxFraction, hit)

  override private[sims] def boundingRadius: Double = halfLength + radius
  override private[sims] def projectMin(ax: Double, ay: Double): Double =
    refresh()
    math.min(endXs(0) * ax + endYs(0) * ay, endXs(1) * ax + endYs(1) * ay) - radius
  override private[sims] def projectMax(ax: Double, ay: Double): Double =
    refresh()
    math.max(endXs(0) * ax + endYs(0) * ay, endXs(1) * ax + endYs(1) * ay) + radius
  override private[sims] def minX: Double = { refresh(); math.min(endXs(0), endXs(1)) - radius }
  override private[sims] def minY: Double = { refresh(); math.min(endYs(0), endYs(1)) - radius }
  override private[sims] def maxX: Double = { refresh(); math.max(endXs(0), endXs(1)) + radius }
  override private[sims] def maxY: Double = { refresh(); math.max(endYs(0), endYs(1)) + radius }
