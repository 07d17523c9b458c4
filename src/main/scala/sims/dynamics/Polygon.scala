package sims.dynamics

import scala.collection.immutable.ArraySeq
import sims.geometry.{AABB, ConvexPolygon, PolygonMath, PortableMath, Projection, Vector2D}

/** A convex polygonal shape defined by its vertices around its centre at rotation 0
  * (counter-clockwise). World vertices are recomputed lazily after the shape moves, into
  * arrays reused for the shape's whole life.
  */
abstract class Polygon(localVertices: IndexedSeq[Vector2D]) extends Shape with ConvexPolygon:
  private val count = localVertices.length
  private val localX = localVertices.map(_.x).toArray
  private val localY = localVertices.map(_.y).toArray
  private val worldX = new Array[Double](count)
  private val worldY = new Array[Double](count)
  // Outward unit side normals, world frame: the SAT reads each several times per test.
  private val normalX = new Array[Double](count)
  private val normalY = new Array[Double](count)
  private var boxMinX, boxMinY, boxMaxX, boxMaxY = 0.0
  private var current = false
  private var normalsCurrent = false
  // Cosine and sine of the rotation they were last computed for: a move without turning
  // (common in position correction) needs no new ones.
  private var trigAngle = Double.NaN
  private var cosine, sine = 0.0

  override protected def moved(): Unit =
    current = false
    normalsCurrent = false

  override private[sims] def refreshCaches(): Unit = refreshNormals()

  override private[sims] def refreshBounds(): Unit = refresh()

  /** Recomputes world vertices and bounds if the shape moved since the last call. */
  private def refresh(): Unit =
    if !current then
      if angle != trigAngle then // NaN never equals itself: the first call computes
        cosine = PortableMath.cos(angle)
        sine = PortableMath.sin(angle)
        trigAngle = angle
      val c = cosine
      val s = sine
      boxMinX = Double.PositiveInfinity; boxMinY = Double.PositiveInfinity
      boxMaxX = Double.NegativeInfinity; boxMaxY = Double.NegativeInfinity
      var i = 0
      while i < count do
        val vx = x + localX(i) * c - localY(i) * s
        val vy = y + localX(i) * s + localY(i) * c
        worldX(i) = vx
        worldY(i) = vy
        if vx < boxMinX then boxMinX = vx
        if vx > boxMaxX then boxMaxX = vx
        if vy < boxMinY then boxMinY = vy
        if vy > boxMaxY then boxMaxY = vy
        i += 1
      current = true

  /** Recomputes the side normals if the shape moved since they were last computed: only the
    * SAT reads them, projections and bounds do not.
    */
  private def refreshNormals(): Unit =
    refresh()
    if !normalsCurrent then
      PolygonMath.sideNormals(worldX, worldY, count, normalX, normalY)
      normalsCurrent = true

  def vertices: IndexedSeq[Vector2D] =
    refresh()
    ArraySeq.tabulate(count)(i => Vector2D(worldX(i), worldY(i)))

  override private[sims] val boundingRadius: Double = (0 until count).map(i => PortableMath.hypot(localX(i), localY(i))).max

  override private[sims] def vertexCount: Int = count
  // The library polygon's own arrays, current: no copy.
  override private[sims] def vertexXs: Array[Double] = { refresh(); worldX }
  override private[sims] def vertexYs: Array[Double] = { refresh(); worldY }
  override private[sims] def sideNormalXs: Array[Double] = { refreshNormals(); normalX }
  override private[sims] def sideNormalYs: Array[Double] = { refreshNormals(); normalY }

  override def project(axis: Vector2D): Projection =
    Projection(axis, projectMin(axis.x, axis.y), projectMax(axis.x, axis.y))

  override def AABB: AABB =
    refresh()
    new sims.geometry.AABB(Vector2D(boxMinX, boxMinY), Vector2D(boxMaxX, boxMaxY))

  override def contains(point: Vector2D): Boolean =
    refresh()
    PolygonMath.contains(worldX, worldY, count, point.x, point.y)

  override private[sims] def projectMin(ax: Double, ay: Double): Double =
    refresh()
    PolygonMath.projectionMin(worldX, worldY, count, ax, ay)

  override private[sims] def projectMax(ax: Double, ay: Double): Double =
    refresh()
    PolygonMath.projectionMax(worldX, worldY, count, ax, ay)

  override private[sims] def minX: Double = { refresh(); boxMinX }
  override private[sims] def minY: Double = { refresh(); boxMinY }
  override private[sims] def maxX: Double = { refresh(); boxMaxX }
  override private[sims] def maxY: Double = { refresh(); boxMaxY }
