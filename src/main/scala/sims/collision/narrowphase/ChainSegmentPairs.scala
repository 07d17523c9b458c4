package sims.collision.narrowphase

import sims.collision.{Collision, ShapeSeparation}
import sims.collision.manifold.{ChainSegmentManifold, CapsuleManifold, Manifold}
import sims.dynamics.{ChainSegment, Circle, RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

/** The chain segment's entries in the narrowphase registry: against circle, polygon, capsule
  * (and edge) and chain segment, both ways round. The classic test and contact and the
  * separation are the edge's (a chain collides as its edges under the classic step); the soft
  * manifold is smooth and one-sided ([[ChainSegmentManifold]]).
  */
private[sims] object ChainSegmentPairs:
  private type Polygon = Shape & ConvexPolygon

  /** This kind's entries. */
  val entries: Seq[PairFunctions] = Seq(
    Smooth(PairKind.ChainCircle, PairKind.CapsuleCircle, chainFirst = true),
    Smooth(PairKind.CircleChain, PairKind.CircleCapsule, chainFirst = false),
    Smooth(PairKind.ChainPolygon, PairKind.CapsulePolygon, chainFirst = true),
    Smooth(PairKind.PolygonChain, PairKind.PolygonCapsule, chainFirst = false),
    Smooth(PairKind.ChainCapsule, PairKind.CapsuleCapsule, chainFirst = true),
    Smooth(PairKind.CapsuleChain, PairKind.CapsuleCapsule, chainFirst = false),
    Smooth(PairKind.ChainChain, PairKind.CapsuleCapsule, chainFirst = true))

  /** A chain segment's pair: the edge's entry `asEdge` for all but the soft manifold. */
  private final class Smooth(kind: PairKind, asEdge: PairKind, chainFirst: Boolean) extends PairFunctions(kind):
    private val edge = CapsulePairs.entries.find(_.kind == asEdge).get

    def colliding(a: Shape, b: Shape): Boolean = edge.colliding(a, b)

    def collision(a: Shape, b: Shape): Collision = edge.collision(a, b)

    def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision = edge.collide(slot, a, b, pool)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean = edge.separation(a, b, out)

    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      val segment = (if chainFirst then a else b).asInstanceOf[ChainSegment]
      val other = if chainFirst then b else a
      other match
        case c: Circle => ChainSegmentManifold.collide(segment, c, speculativeDistance, out)
        case p: ConvexPolygon => ChainSegmentManifold.collide(segment, p.asInstanceOf[Polygon], speculativeDistance, linearSlop, out)
        case _: ChainSegment => CapsuleManifold.collide(segment, other.asInstanceOf[RoundedSegment], speculativeDistance, linearSlop, out)
        case r: RoundedSegment => ChainSegmentManifold.collide(segment, r, speculativeDistance, linearSlop, out)
        case _ => out.clear()
      if !chainFirst then ChainSegmentManifold.flip(out)
