package sims.collision.narrowphase

import sims.collision.{CapsuleCollision, Collision, ShapeSeparation}
import sims.collision.manifold.{CapsuleCircleManifold, CapsuleManifold, Manifold, PolygonManifold}
import sims.dynamics.{Circle, RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

/** The capsule's (and edge's: a segment with radius 0) entries in the narrowphase registry:
  * capsule against circle, capsule and polygon, both ways round. The classic contact takes the
  * capsule as reference against a circle and the polygon against a capsule (see
  * [[sims.collision.CapsuleCollision]]).
  */
private[sims] object CapsulePairs:
  private type Polygon = Shape & ConvexPolygon

  /** This kind's entries. */
  val entries: Seq[PairFunctions] =
    Seq(CapsuleCircle, CircleCapsule, CapsuleCapsule, PolygonCapsule, CapsulePolygon)

  /** The classic test and contact of every capsule kind, with the reference shape first or second. */
  private abstract class CapsuleKind(kind: PairKind, referenceFirst: Boolean) extends PairFunctions(kind):
    def colliding(a: Shape, b: Shape): Boolean = CapsuleCollision.colliding(a, b)

    def collision(a: Shape, b: Shape): Collision = CapsuleCollision(a, b)

    def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision =
      // Each slot keeps its own object, as for circles.
      if slot.capsule == null then slot.capsule = CapsuleCollision.empty()
      val touching =
        if referenceFirst then slot.capsule.compute(a, b, pool.scratch) else slot.capsule.compute(b, a, pool.scratch)
      if touching then slot.capsule else null

  private object CapsuleCircle extends CapsuleKind(PairKind.CapsuleCircle, referenceFirst = true):
    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      CapsuleCircleManifold.collide(a.asInstanceOf[RoundedSegment], b.asInstanceOf[Circle], speculativeDistance, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      val c = b.asInstanceOf[Circle]
      out.segmentPoint(a.asInstanceOf[RoundedSegment], c.x, c.y, c.radius)

  private object CircleCapsule extends CapsuleKind(PairKind.CircleCapsule, referenceFirst = false):
    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      CapsuleCircleManifold.collide(a.asInstanceOf[Circle], b.asInstanceOf[RoundedSegment], speculativeDistance, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      val c = a.asInstanceOf[Circle]
      out.segmentPoint(b.asInstanceOf[RoundedSegment], c.x, c.y, c.radius) && out.flip()

  private object CapsuleCapsule extends CapsuleKind(PairKind.CapsuleCapsule, referenceFirst = true):
    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      CapsuleManifold.collide(a.asInstanceOf[RoundedSegment], b.asInstanceOf[RoundedSegment], speculativeDistance,
        linearSlop, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      out.segments(a.asInstanceOf[RoundedSegment], b.asInstanceOf[RoundedSegment])

  private object PolygonCapsule extends CapsuleKind(PairKind.PolygonCapsule, referenceFirst = true):
    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      PolygonManifold.collide(a.asInstanceOf[Polygon], b.asInstanceOf[RoundedSegment], speculativeDistance,
        linearSlop, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      out.polygonSegment(a.asInstanceOf[ConvexPolygon], b.asInstanceOf[RoundedSegment])

  private object CapsulePolygon extends CapsuleKind(PairKind.CapsulePolygon, referenceFirst = false):
    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      PolygonManifold.collide(a.asInstanceOf[RoundedSegment], b.asInstanceOf[Polygon], speculativeDistance,
        linearSlop, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      out.polygonSegment(b.asInstanceOf[ConvexPolygon], a.asInstanceOf[RoundedSegment]) && out.flip()
