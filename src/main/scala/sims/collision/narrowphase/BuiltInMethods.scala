package sims.collision.narrowphase

import sims.collision.Collision
import sims.dynamics.Shape

/** The built-in narrowphase methods (SiMS's contact rules, docs/collisions.md): partial functions for the detector's
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

  // ShapeKind.of is the one place that says which class is which kind.
  private def is(kind: ShapeKind, shape: Shape): Boolean = ShapeKind.of(shape) == kind

  /** The tests, in the order the detector's list starts with: the registry's, by pair kind. */
  val tests: Seq[PartialFunction[(Shape, Shape), Boolean]] =
    PairKind.values.toSeq.map(k => Test(k, PairFunctions.of(k).colliding))

  /** The collision constructors, in the order the detector's list starts with. */
  val collisions: Seq[PartialFunction[(Shape, Shape), Collision]] =
    PairKind.values.toSeq.map(k => Make(k, PairFunctions.of(k).collision))
