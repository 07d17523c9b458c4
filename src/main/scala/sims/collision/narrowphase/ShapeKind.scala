package sims.collision.narrowphase

import sims.dynamics.{ChainSegment, Circle, RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

/** The built-in kinds of shapes the narrowphase has its own functions for. A shape of another
  * kind (a user's) goes through the detector's partial-function lists. Capsules and edges are
  * one kind: a segment with a radius (0 for an edge); a chain's segment, an edge that knows
  * its neighbours, is a kind of its own.
  */
private[sims] enum ShapeKind:
  case Circle, Polygon, Capsule, Chain

private[sims] object ShapeKind:
  /** Every built-in kind's entries in the narrowphase registry ([[PairFunctions]]): a kind's
    * file fills its pairs with the kinds listed before it, both ways round.
    */
  def entries: Seq[PairFunctions] = CirclePairs.entries ++ PolygonPairs.entries ++ CapsulePairs.entries ++ ChainSegmentPairs.entries

  /** The kind of `shape`, or null for a user kind. */
  def of(shape: Shape): ShapeKind = shape match
    case _: Circle => ShapeKind.Circle
    case _: ConvexPolygon => ShapeKind.Polygon
    case _: ChainSegment => ShapeKind.Chain
    case _: RoundedSegment => ShapeKind.Capsule
    case _ => null

/** A pair of built-in kinds, in the order (first, second) of a candidate pair: the key of the
  * narrowphase's table of built-in functions.
  */
private[sims] enum PairKind(val first: ShapeKind, val second: ShapeKind):
  /** Which sides are circles: 1 the first, 2 the second. */
  val circleSides: Int = (if first == ShapeKind.Circle then 1 else 0) | (if second == ShapeKind.Circle then 2 else 0)

  case CircleCircle extends PairKind(ShapeKind.Circle, ShapeKind.Circle)
  case PolygonPolygon extends PairKind(ShapeKind.Polygon, ShapeKind.Polygon)
  case PolygonCircle extends PairKind(ShapeKind.Polygon, ShapeKind.Circle)
  case CirclePolygon extends PairKind(ShapeKind.Circle, ShapeKind.Polygon)
  case CapsuleCircle extends PairKind(ShapeKind.Capsule, ShapeKind.Circle)
  case CircleCapsule extends PairKind(ShapeKind.Circle, ShapeKind.Capsule)
  case CapsuleCapsule extends PairKind(ShapeKind.Capsule, ShapeKind.Capsule)
  case PolygonCapsule extends PairKind(ShapeKind.Polygon, ShapeKind.Capsule)
  case CapsulePolygon extends PairKind(ShapeKind.Capsule, ShapeKind.Polygon)
  case ChainCircle extends PairKind(ShapeKind.Chain, ShapeKind.Circle)
  case CircleChain extends PairKind(ShapeKind.Circle, ShapeKind.Chain)
  case ChainPolygon extends PairKind(ShapeKind.Chain, ShapeKind.Polygon)
  case PolygonChain extends PairKind(ShapeKind.Polygon, ShapeKind.Chain)
  case ChainCapsule extends PairKind(ShapeKind.Chain, ShapeKind.Capsule)
  case CapsuleChain extends PairKind(ShapeKind.Capsule, ShapeKind.Chain)
  case ChainChain extends PairKind(ShapeKind.Chain, ShapeKind.Chain)

private[sims] object PairKind:
  private val byKinds: Array[PairKind] =
    val n = ShapeKind.values.length
    val table = new Array[PairKind](n * n)
    for k <- PairKind.values do table(k.first.ordinal * n + k.second.ordinal) = k
    table

  /** The pair of kinds (first, second), or null when either is null (a user kind). */
  def of(first: ShapeKind, second: ShapeKind): PairKind =
    if first == null || second == null then null else byKinds(first.ordinal * ShapeKind.values.length + second.ordinal)
