package sims.collision.narrowphase

import sims.collision.{CapsuleCollision, CircleCollision, Collision, PolyCircleCollision, PolyCollision}
import sims.dynamics.{Circle, RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

/** The built-in narrowphase methods (SPEC section 4): partial functions for the detector's
  * lists, where users see, reorder or shadow them, each also carrying its [[PairKind]] and a
  * direct two-argument entry that skips building a tuple on the hot path.
  */
private[sims] object BuiltInMethods:
  /** A built-in test. */
  final class Test(val kind: PairKind, val direct: (Shape, Shape) => Boolean)
      extends PartialFunction[(Shape, Shape), Boolean]:
    def isDefinedAt(pair: (Shape, Shape)): Boolean = matches(kind, pair)
    def apply(pair: (Shape, Shape)): Boolean = direct(pair._1, pair._2)

  /** A built-in collision constructor. */
  final class Make(val kind: PairKind, val direct: (Shape, Shape) => Collision)
      extends PartialFunction[(Shape, Shape), Collision]:
    def isDefinedAt(pair: (Shape, Shape)): Boolean = matches(kind, pair)
    def apply(pair: (Shape, Shape)): Collision = direct(pair._1, pair._2)

  private def matches(kind: PairKind, pair: (Shape, Shape)): Boolean =
    is(kind.first, pair._1) && is(kind.second, pair._2)

  private def is(kind: ShapeKind, shape: Shape): Boolean = kind match
    case ShapeKind.Circle => shape.isInstanceOf[Circle]
    case ShapeKind.Polygon => shape.isInstanceOf[ConvexPolygon]
    case ShapeKind.Capsule => shape.isInstanceOf[RoundedSegment]

  private type Polygon = Shape & ConvexPolygon

  val circleCircleTest = Test(PairKind.CircleCircle,
    (a, b) => CircleCollision.colliding(a.asInstanceOf[Circle], b.asInstanceOf[Circle]))
  val polygonPolygonTest = Test(PairKind.PolygonPolygon,
    (a, b) => PolyCollision.colliding(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon]))
  val polygonCircleTest = Test(PairKind.PolygonCircle,
    (a, b) => PolyCircleCollision.colliding(a.asInstanceOf[Polygon], b.asInstanceOf[Circle]))
  val circlePolygonTest = Test(PairKind.CirclePolygon,
    (a, b) => PolyCircleCollision.colliding(b.asInstanceOf[Polygon], a.asInstanceOf[Circle]))

  val circleCircleCollision = Make(PairKind.CircleCircle,
    (a, b) => CircleCollision(a.asInstanceOf[Circle], b.asInstanceOf[Circle]))
  val polygonPolygonCollision = Make(PairKind.PolygonPolygon,
    (a, b) => PolyCollision(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon]))
  val polygonCircleCollision = Make(PairKind.PolygonCircle,
    (a, b) => PolyCircleCollision(a.asInstanceOf[Polygon], b.asInstanceOf[Circle]))
  val circlePolygonCollision = Make(PairKind.CirclePolygon,
    (a, b) => PolyCircleCollision(b.asInstanceOf[Polygon], a.asInstanceOf[Circle]))

  /** The kinds with a capsule or an edge: one test and one constructor serve them all. */
  private val capsuleKinds = Seq(PairKind.CapsuleCircle, PairKind.CircleCapsule, PairKind.CapsuleCapsule,
    PairKind.PolygonCapsule, PairKind.CapsulePolygon)
  val capsuleTests: Seq[Test] = capsuleKinds.map(Test(_, CapsuleCollision.colliding))
  val capsuleCollisions: Seq[Make] = capsuleKinds.map(Make(_, CapsuleCollision(_, _)))

  /** The tests, in the order the detector's list starts with. */
  def tests: Seq[PartialFunction[(Shape, Shape), Boolean]] =
    Seq(circleCircleTest, polygonPolygonTest, polygonCircleTest, circlePolygonTest) ++ capsuleTests

  /** The collision constructors, in the order the detector's list starts with. */
  def collisions: Seq[PartialFunction[(Shape, Shape), Collision]] =
    Seq(circleCircleCollision, polygonPolygonCollision, polygonCircleCollision, circlePolygonCollision) ++
      capsuleCollisions
