package sims.collision

import sims.Defaults
import sims.collision.manifold.{CapsuleCircleManifold, CapsuleManifold, Manifold, PolygonManifold}
import sims.dynamics.{Circle, RoundedSegment, Shape}
import sims.geometry.{ConvexPolygon, Vector2D}

/** Collision of a capsule or an edge (a segment with a radius, 0 for an edge) with a circle, a
  * polygon, or another capsule or edge: SiMS's contact rules carried over to a shape that is a
  * segment grown by a radius. The shapes collide when they touch or overlap; normal and points
  * come from their closest features, as the soft step's manifold finds them with no
  * speculative distance:
  *
  *  - capsule-circle: the capsule's core point q nearest the centre stands for a circle's
  *    centre, then as circle-circle: n = unit(centre - q), one point `centre - n r`;
  *  - capsule-capsule: n from the closest point of the first core to that of the second, one
  *    point on the second's outline; two points when the cores lie along each other (parallel
  *    within [[sims.collision.manifold.CapsuleManifold.ParallelSine]]), the second's clipped to
  *    the first's length;
  *  - polygon-capsule: the capsule as a two-vertex polygon with a radius, by the separating axes
  *    and clipping of the polygon manifold: one or two points.
  *
  * The reference (`shape1`, which the normal points away from) is the capsule against a circle,
  * the polygon against a capsule, and the pair's first shape for two capsules. Each point lies
  * where `shape2`'s outline reaches deepest into `shape1` (as in SiMS's circle-circle and
  * polygon-circle cases). Position correction reads the shapes' projections, in which an edge
  * counts as solid on its far side from the other shape (see `Collision.overlapAlong`).
  */
final class CapsuleCollision private () extends Collision:
  private var reference: Shape = null
  private var incident: Shape = null
  override private[sims] def solvedInPlace: Boolean = true
  ensureCapacity(Manifold.MaximumPoints)

  def shape1: Shape = reference
  def shape2: Shape = incident
  def normal: Vector2D = Vector2D(normalX, normalY)
  def points: Iterable[Vector2D] = pointVectors

  /** Recomputes this collision for (reference, incident) from their current positions, with
    * `manifold` as scratch; true if they touch.
    */
  private[collision] def compute(referenceShape: Shape, incidentShape: Shape, manifold: Manifold): Boolean =
    reference = referenceShape
    incident = incidentShape
    CapsuleCollision.contact(referenceShape, incidentShape, manifold)
    normalX = manifold.normalX
    normalY = manifold.normalY
    pointCount = manifold.pointCount
    var i = 0
    while i < pointCount do
      // From the middle of the two surfaces to shape2's: half the (negative) separation along n.
      val half = 0.5 * manifold.separation(i)
      pointXs(i) = manifold.x(i) + normalX * half
      pointYs(i) = manifold.y(i) + normalY * half
      i += 1
    pointCount > 0

/** The narrowphase of pairs with a capsule or an edge. */
object CapsuleCollision:
  /** The collision of `a` and `b` (one a capsule or an edge, the other a circle, polygon,
    * capsule or edge) from their current positions; without points if they do not touch.
    */
  def apply(a: Shape, b: Shape): CapsuleCollision =
    val collision = empty()
    if referenceFirst(a, b) then collision.compute(a, b, Manifold()) else collision.compute(b, a, Manifold())
    collision

  /** True when `a` and `b` (as for `apply`) touch or overlap. */
  def colliding(a: Shape, b: Shape): Boolean =
    val manifold = Manifold()
    if referenceFirst(a, b) then contact(a, b, manifold) else contact(b, a, manifold)
    manifold.pointCount > 0

  /** A collision object without shapes yet, for the narrowphase to fill. */
  private[collision] def empty(): CapsuleCollision = new CapsuleCollision()

  /** Whether `a` is the reference of the pair (a, b): unless it is the circle, or a capsule
    * against a polygon.
    */
  private def referenceFirst(a: Shape, b: Shape): Boolean =
    !(a.isInstanceOf[Circle] || (a.isInstanceOf[RoundedSegment] && b.isInstanceOf[ConvexPolygon]))

  /** Fills `manifold` for the pair, reference first, with no speculative distance (nested
    * matches: a tuple would be made on every call).
    */
  private def contact(reference: Shape, incident: Shape, manifold: Manifold): Unit =
    reference match
      case capsule: RoundedSegment =>
        incident match
          case circle: Circle => CapsuleCircleManifold.collide(capsule, circle, 0, manifold)
          case other: RoundedSegment => CapsuleManifold.collide(capsule, other, 0, Defaults.LinearSlop, manifold)
          case _ => unsupported(reference, incident)
      case polygon: ConvexPolygon =>
        incident match
          case capsule: RoundedSegment => PolygonManifold.collide(polygon, capsule, 0, Defaults.LinearSlop, manifold)
          case _ => unsupported(reference, incident)
      case _ => unsupported(reference, incident)

  private def unsupported(reference: Shape, incident: Shape): Nothing =
    throw IllegalArgumentException(s"no capsule contact for ${reference.getClass.getSimpleName} " +
      s"and ${incident.getClass.getSimpleName}")
