package sims.collision.narrowphase

import sims.collision.{Collision, ShapeSeparation}
import sims.collision.manifold.Manifold
import sims.dynamics.Shape

/** Everything the library computes for one pair of built-in shape kinds, (first, second) in the
  * order of a candidate pair: the narrowphase registry's entry, serving both steps and the
  * queries. Each shape kind fills its entries in one file (`CirclePairs`, `PolygonPairs`,
  * `CapsulePairs`), [[ShapeKind]] lists them, and the registry (the companion) holds them by
  * [[PairKind]], as Box2D fills its table of collide functions indexed by the two shape types.
  *
  * A pair of a user's kinds has no entry: it goes through the detector's partial-function lists
  * (see [[Narrowphase]]).
  */
private[sims] abstract class PairFunctions(val kind: PairKind):
  /** The classic step's test (SiMS's contact rules, docs/collisions.md): whether the shapes touch or overlap. */
  def colliding(a: Shape, b: Shape): Boolean

  /** The classic step's contact of two colliding shapes, a new object (SiMS's contact rules, docs/collisions.md). */
  def collision(a: Shape, b: Shape): Collision

  /** The classic step's contact from the current positions, refilling the collision object the
    * slot holds (or lending it one from `pool`), or null if the shapes do not collide.
    */
  def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision

  /** The soft step's manifold (at most two points with feature ids, speculative points up to
    * `speculativeDistance` apart) into `out`; `lastSide` is the side of a polygon the pair's
    * last manifold was measured from (-1 for none).
    */
  def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
      out: Manifold): Unit

  /** The distance between the outlines (minus the depth when overlapping) and the normal along
    * which it is their gap, into `out` (see [[ShapeSeparation]]); the contact events' hysteresis
    * and the bullets' time of impact (by conservative advancement) are made of it.
    */
  def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean

/** The registry: the entry of each pair of built-in kinds (each kind's entries listed in
  * [[ShapeKind]]'s file).
  */
private[sims] object PairFunctions:
  private val table: Array[PairFunctions] =
    val entries = ShapeKind.entries
    val byKind = new Array[PairFunctions](PairKind.values.length)
    for e <- entries do
      require(byKind(e.kind.ordinal) == null, s"two entries for ${e.kind}")
      byKind(e.kind.ordinal) = e
    for k <- PairKind.values do require(byKind(k.ordinal) != null, s"no entry for $k")
    byKind

  /** The entry of a pair kind. */
  def of(kind: PairKind): PairFunctions = table(kind.ordinal)

  /** The entry for shapes (a, b), or null when either is not of a built-in kind. */
  def of(a: Shape, b: Shape): PairFunctions =
    val kind = PairKind.of(ShapeKind.of(a), ShapeKind.of(b))
    if kind == null then null else table(kind.ordinal)
