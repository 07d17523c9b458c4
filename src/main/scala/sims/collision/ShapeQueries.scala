package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.Defaults
import sims.collision.broadphase.{Broadphase, UniformGrid}
import sims.dynamics.{Shape, World}
import sims.geometry.{RayMath, Vector2D}

/** The world's queries (`World.rayCast`, `rayCastAll`, `query`, `shapesAt`) through the world's
  * broadphase, filled with every shape (collidable or not), so a query looks at the shapes near
  * its box or ray only. The grid takes the shapes' bounds again at the first query after
  * anything moved or a step used the grid (the world says when: `stale`), so queries see the
  * current positions whenever they are made; between moves, queries reuse it.
  */
private[sims] final class ShapeQueries(world: World):
  /** Set by the world whenever a shape may have moved, joined or left, or a step used the grid,
    * since the grid last took every shape's bounds for the queries.
    */
  var stale: Boolean = true

  private def fresh(): UniformGrid =
    val stages = world.collisionPipeline
    val grid = stages.broadphase
    if stale || !stages.holdsQueryBounds then
      grid.gridSide = world.detector match
        case detector: GridDetector => detector.gridSide
        case _ => Defaults.GridSide
      grid.update(world.shapeBuffer, 0, 0, everyShape = true)
      stale = false
      stages.holdsQueryBounds = true
    grid

  /** The nearest hit of the segment from `from` to `to` among the shapes `filter` accepts. */
  def rayCast(from: Vector2D, to: Vector2D, filter: Shape => Boolean): Option[RayHit] =
    val nearest = Nearest(from, to, filter)
    fresh().rayCast(from.x, from.y, to.x, to.y, nearest)
    nearest.result

  /** Every hit of the segment, nearest first (on equal fractions, in world order). */
  def rayCastAll(from: Vector2D, to: Vector2D, filter: Shape => Boolean): IndexedSeq[RayHit] =
    val all = All(from, to, filter)
    fresh().rayCast(from.x, from.y, to.x, to.y, all)
    all.hits.sortBy(h => (h.fraction, h.shape.worldIndex)).toIndexedSeq

  /** The shapes whose bounds overlap the box, in world order. */
  def query(minX: Double, minY: Double, maxX: Double, maxY: Double, filter: Shape => Boolean): IndexedSeq[Shape] =
    val found = ArrayBuffer.empty[Shape]
    fresh().query(minX, minY, maxX, maxY, found)
    found.filter(filter).toIndexedSeq

  /** Adds to `found` the shapes whose bounds overlap the box, in world order (no filter, no copy). */
  def near(minX: Double, minY: Double, maxX: Double, maxY: Double, found: ArrayBuffer[Shape]): Unit =
    fresh().query(minX, minY, maxX, maxY, found)

  private val sweep = ShapeCast()
  private val separation = ShapeSeparation()

  /** The first shape `shape` (at rotation `shape.rotation`) meets when swept from `from` to
    * `to` without turning, among those `filter` accepts, with where, the hit shape's normal and
    * the fraction of the path; None if it meets none. Puts `shape` back where it was.
    */
  def castShape(shape: Shape, from: Vector2D, to: Vector2D, filter: Shape => Boolean): Option[RayHit] =
    val home = shape.pos
    val angle = shape.rotation
    val dx = to.x - from.x
    val dy = to.y - from.y
    shape.place(from.x, from.y, angle)
    val start = shape.AABB
    shape.place(to.x, to.y, angle)
    val end = shape.AABB
    val found = ArrayBuffer.empty[Shape]
    fresh().query(math.min(start.minVertex.x, end.minVertex.x), math.min(start.minVertex.y, end.minVertex.y),
      math.max(start.maxVertex.x, end.maxVertex.x), math.max(start.maxVertex.y, end.maxVertex.y), found)
    var best: Option[RayHit] = None
    var bestFraction = 1.0
    for other <- found do
      if (other ne shape) && filter(other) then
        val t = sweep.fraction(shape, from.x, from.y, angle, dx, dy, other, bestFraction)
        // On equal fractions the shape first in world order (found is in world order).
        if t <= bestFraction && (best.isEmpty || t < bestFraction) then
          bestFraction = t
          best = Some(RayHit(other, Vector2D(sweep.pointX, sweep.pointY), Vector2D(sweep.normalX, sweep.normalY), t))
    shape.place(home.x, home.y, angle)
    best

  /** The shapes `shape` overlaps where it is (by more than touching), among those `filter`
    * accepts, in world order; `shape` itself and its body's other shapes are not among them.
    */
  def overlapping(shape: Shape, filter: Shape => Boolean): IndexedSeq[Shape] =
    val box = shape.AABB
    val found = ArrayBuffer.empty[Shape]
    fresh().query(box.minVertex.x, box.minVertex.y, box.maxVertex.x, box.maxVertex.y, found)
    found.iterator.filter(other =>
      (other ne shape) && (shape.body == null || (other.body ne shape.body)) && filter(other) &&
        ShapeCast.overlap(separation, shape, other)).toIndexedSeq

  /** The shapes that contain the point, in world order. */
  def shapesAt(point: Vector2D, filter: Shape => Boolean): IndexedSeq[Shape] =
    query(point.x, point.y, point.x, point.y, s => s.contains(point) && filter(s))

  /** Casts the ray against one shape: its own `rayCast` if its class has one, else the
    * library's.
    */
  private abstract class Caster(from: Vector2D, to: Vector2D, filter: Shape => Boolean) extends Broadphase.RayVisitor:
    private val dx = to.x - from.x
    private val dy = to.y - from.y
    protected val hit = RayMath.Hit()

    /** True if the ray enters `shape` at a fraction at most `limit` (then in `hit`). */
    protected def cast(shape: Shape, limit: Double): Boolean =
      if !filter(shape) then false
      else if Shape.castsItself(shape) then
        shape.rayCast(from, to) match
          case Some(own) if own.fraction >= 0 && own.fraction <= limit =>
            hit.fraction = own.fraction
            hit.normalX = own.normal.x
            hit.normalY = own.normal.y
            true
          case _ => false
      else shape.castRay(from.x, from.y, dx, dy, limit, hit)

    /** The hit in `hit` on `shape` as a result. */
    protected def toHit(shape: Shape): RayHit =
      RayHit(shape, Vector2D(from.x + hit.fraction * dx, from.y + hit.fraction * dy),
        Vector2D(hit.normalX, hit.normalY), hit.fraction)

  /** Keeps the nearest hit (on equal fractions, the shape first in world order). */
  private final class Nearest(from: Vector2D, to: Vector2D, filter: Shape => Boolean)
      extends Caster(from, to, filter):
    var result: Option[RayHit] = None
    def visit(shape: Shape, limit: Double): Double =
      // `cast` finds hits up to `limit`, the nearest so far: a tie goes to the earlier shape.
      if cast(shape, limit) && result.forall(r => hit.fraction < r.fraction || shape.worldIndex < r.shape.worldIndex) then
        result = Some(toHit(shape))
        hit.fraction
      else limit

  /** Keeps every hit. */
  private final class All(from: Vector2D, to: Vector2D, filter: Shape => Boolean) extends Caster(from, to, filter):
    val hits = ArrayBuffer.empty[RayHit]
    def visit(shape: Shape, limit: Double): Double =
      if cast(shape, limit) then hits += toHit(shape)
      limit
