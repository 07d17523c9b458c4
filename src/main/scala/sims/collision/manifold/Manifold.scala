package sims.collision.manifold

// The contact of two shapes as the soft step (see docs/two-solvers.md) consumes it: one normal
// and at most two points, each with its separation and a feature id. The narrowphase
// functions of this package fill one reused Manifold in place, so colliding allocates nothing;
// the solver copies out what it keeps before the Manifold is filled again.

/** The contact manifold of a pair of shapes (A, B): a unit normal from A towards B and at most
  * two points, each midway between the two surfaces, with its signed separation along the
  * normal (negative: overlap; positive, up to the speculative distance: apart) and a feature
  * id that stays the same while the same features touch (for warm starting). Filled in place
  * by [[CircleManifold]], [[PolygonCircleManifold]] and [[PolygonManifold]].
  */
private[sims] final class Manifold:

  /** Number of points, 0 to 2; 0 means no contact within the speculative distance. */
  var pointCount: Int = 0

  /** x of the unit normal, pointing from shape A (the first argument) towards shape B. */
  var normalX: Double = 0

  /** y of the unit normal. */
  var normalY: Double = 0

  /** World x of each point, midway between the two surfaces. */
  val x: Array[Double] = new Array[Double](Manifold.MaximumPoints)

  /** World y of each point. */
  val y: Array[Double] = new Array[Double](Manifold.MaximumPoints)

  /** Signed distance between the surfaces along the normal at each point (negative: overlap). */
  val separation: Array[Double] = new Array[Double](Manifold.MaximumPoints)

  /** Feature id of each point; each function's documentation says how it is made. */
  val id: Array[Int] = new Array[Int](Manifold.MaximumPoints)

  /** Polygon-circle only: the polygon side the contact was measured from, to be passed back as
    * `lastSide` in the next step; -1 when there is no contact or for the other kinds.
    */
  var polygonSide: Int = -1

  /** Empties the manifold: no points, a zero normal, no polygon side. */
  def clear(): Unit =
    pointCount = 0
    normalX = 0
    normalY = 0
    polygonSide = -1

  /** Appends a point (the caller keeps to at most two). */
  private[manifold] def addPoint(pointX: Double, pointY: Double, pointSeparation: Double, pointId: Int): Unit =
    x(pointCount) = pointX
    y(pointCount) = pointY
    separation(pointCount) = pointSeparation
    id(pointCount) = pointId
    pointCount += 1

  /** Turns the normal round, for a pair whose shapes were given to a function the other way. */
  private[manifold] def flipNormal(): Unit =
    normalX = -normalX
    normalY = -normalY

  override def toString: String =
    val points = (0 until pointCount)
      .map(i => s"(${x(i)}, ${y(i)}) separation ${separation(i)} id ${id(i)}")
      .mkString("[", ", ", "]")
    val side = if polygonSide >= 0 then s", polygonSide = $polygonSide" else ""
    s"Manifold(normal = ($normalX, $normalY), points = $points$side)"

/** Sizes of [[Manifold]]. */
private[sims] object Manifold:
  /** A manifold of two convex shapes in the plane needs at most two points. */
  val MaximumPoints: Int = 2
