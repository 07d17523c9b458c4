package sims.collision.narrowphase

import sims.dynamics.{Circle, Shape}
import sims.geometry.ConvexPolygon

/** The built-in kinds of shapes the narrowphase has its own functions for. A shape of another
  * kind (a user's) goes through the detector's partial-function lists.
  */
private[sims] enum ShapeKind:
  case Circle, Polygon

private[sims] object ShapeKind:
  /** The kind of `shape`, or null for a user kind. */
  def of(shape: Shape): ShapeKind = shape match
    case _: Circle => ShapeKind.Circle
    case _: ConvexPolygon => ShapeKind.Polygon
    case _ => null

/** A pair of built-in kinds, in the order (first, second) of a candidate pair: the key of the
  * narrowphase's table of built-in functions.
  */
private[sims] enum PairKind(val first: ShapeKind, val second: ShapeKind):
  case CircleCircle extends PairKind(ShapeKind.Circle, ShapeKind.Circle)
  case PolygonPolygon extends PairKind(ShapeKind.Polygon, ShapeKind.Polygon)
  case PolygonCircle extends PairKind(ShapeKind.Polygon, ShapeKind.Circle)
  case CirclePolygon extends PairKind(ShapeKind.Circle, ShapeKind.Polygon)
