package sims.collision.narrowphase

import scala.collection.mutable.ArrayBuffer
import sims.collision.Collision
import sims.dynamics.Shape

/** The second stage of collision detection: for each candidate pair, which methods its shapes'
  * classes have, and, for the classic step, whether they collide and their [[Collision]] (SiMS's
  * contact rules).
  *
  * The detector's `detectionMethods` and `collisionMethods` lists are the extension point. They
  * fill this table: a map from a pair of shape classes to the first test and the first
  * constructor defined for it, resolved once per class pair (so a method must be defined or not
  * by the shapes' classes alone, as type patterns are) and dropped whenever a list changes.
  * When both chosen methods are the same built-in [[PairKind]], the pair is resolved into the
  * registry's entry of that kind ([[PairFunctions]]), which both steps use: the classic step
  * calls it directly and refills the pair slot's reusable collision object instead of going
  * through the partial functions, and reuses the slot's last result while neither body moved;
  * the soft step takes its manifold.
  */
private[sims] final class Narrowphase:
  import Narrowphase.*

  private var detectionSnapshot = Array.empty[AnyRef]
  private var collisionSnapshot = Array.empty[AnyRef]
  private val table = java.util.HashMap[(Class[?], Class[?]), Resolved]()
  // A few recent class pairs, searched by identity before the map: scenes have a handful of
  // class pairs, looked up for every candidate pair, and the map's key would be a new tuple.
  // Written out here rather than through a `RecentMethods` (as a shared stage's colliders
  // keep theirs): this is every pair's path on one thread, and the call through another
  // object measured 1.2% slower on ballpit-4000.
  private val recentClass1 = new Array[Class[?]](RecentSize)
  private val recentClass2 = new Array[Class[?]](RecentSize)
  private val recent = new Array[Resolved](RecentSize)
  private var recentNext = 0

  /** Drops the table if either list changed since the last call; true if it did. */
  def update(detection: ArrayBuffer[PartialFunction[(Shape, Shape), Boolean]],
      collision: ArrayBuffer[PartialFunction[(Shape, Shape), Collision]]): Boolean =
    if !sameContents(detection, detectionSnapshot) || !sameContents(collision, collisionSnapshot) then
      detectionSnapshot = detection.toArray[AnyRef]
      collisionSnapshot = collision.toArray[AnyRef]
      table.clear()
      java.util.Arrays.fill(recentClass1.asInstanceOf[Array[AnyRef]], null)
      java.util.Arrays.fill(recentClass2.asInstanceOf[Array[AnyRef]], null)
      java.util.Arrays.fill(recent.asInstanceOf[Array[AnyRef]], null)
      true
    else false

  private def sameContents(buffer: ArrayBuffer[?], snapshot: Array[AnyRef]): Boolean =
    if buffer.length != snapshot.length then false
    else
      var i = 0
      while i < snapshot.length && (buffer(i).asInstanceOf[AnyRef] eq snapshot(i)) do i += 1
      i == snapshot.length

  /** The classic objects lent to the pair slots (see [[CollisionPool]]). */
  val pool: CollisionPool = CollisionPool()

  /** The collision of the pair in `slot` from the current positions, or null if its shapes do
    * not collide.
    */
  def collide(slot: PairSlot): Collision =
    val a = slot.first
    val b = slot.second
    val r = slot.methods
    val functions = r.functions
    if functions == null then collideGeneral(r, a, b)
    else
      val placements1 = a.body.placements
      val placements2 = b.body.placements
      if (slot.doneFirst eq a) && (slot.doneSecond eq b) && slot.donePlacements1 == placements1 &&
        slot.donePlacements2 == placements2 then
        slot.result
      else
        val c = functions.collide(slot, a, b, pool)
        slot.doneFirst = a
        slot.doneSecond = b
        slot.donePlacements1 = placements1
        slot.donePlacements2 = placements2
        slot.result = c
        c

  /** Gives back the slot's polygon-kind objects that its pair, of the given kind (null: a user
    * kind, or the slot holds no pair this step), does not use.
    */
  def releaseUnused(slot: PairSlot, kind: PairKind): Unit = pool.releaseUnused(slot, kind)

  /** Whether `a` and `b` collide by the test `r` chose for their classes (no collision made). */
  def test(r: Resolved, a: Shape, b: Shape): Boolean =
    r.test match
      case t: BuiltInMethods.Test => t.direct(a, b)
      case t => t((a, b))

  /** A pair whose methods are not one built-in kind: through the partial functions. */
  def collideGeneral(r: Resolved, a: Shape, b: Shape): Collision =
    if !test(r, a, b) then null
    else if r.make == null then
      throw IllegalStateException(s"no collision method for a colliding pair of " +
        s"${a.getClass.getSimpleName} and ${b.getClass.getSimpleName}")
    else
      r.make match
        case m: BuiltInMethods.Make => m.direct(a, b)
        case m => m((a, b))

  /** The methods for the shapes' classes; fails if no detection method covers them. */
  def resolve(a: Shape, b: Shape): Resolved =
    val c1 = a.shapeClass
    val c2 = b.shapeClass
    var k = 0
    while k < RecentSize && !((recentClass1(k) eq c1) && (recentClass2(k) eq c2)) do k += 1
    if k < RecentSize then recent(k)
    else
      val key = (c1, c2)
      var r = table.get(key)
      if r == null then
        val pair = (a, b)
        val test = detectionSnapshot.iterator
          .map(_.asInstanceOf[PartialFunction[(Shape, Shape), Boolean]]).find(_.isDefinedAt(pair))
        val make = collisionSnapshot.iterator
          .map(_.asInstanceOf[PartialFunction[(Shape, Shape), Collision]]).find(_.isDefinedAt(pair))
        if test.isEmpty then
          throw IllegalStateException(s"no detection method for a pair of " +
            s"${c1.getSimpleName} and ${c2.getSimpleName}; append one to detectionMethods")
        r = Resolved(test.get, make.orNull)
        table.put(key, r)
      recentClass1(recentNext) = c1
      recentClass2(recentNext) = c2
      recent(recentNext) = r
      recentNext = (recentNext + 1) % RecentSize
      r

private[sims] object Narrowphase:
  private val RecentSize = 8

  /** The test and the constructor chosen for one pair of classes (the constructor may be
    * missing: then a colliding pair is an error).
    */
  final class Resolved(val test: PartialFunction[(Shape, Shape), Boolean],
      val make: PartialFunction[(Shape, Shape), Collision]):
    /** The built-in kind when test and constructor are the same built-in kind, else null. */
    val kind: PairKind = (test, make) match
      case (t: BuiltInMethods.Test, m: BuiltInMethods.Make) if t.kind == m.kind => t.kind
      case _ => null
    /** The registry's entry of that kind, used by both steps and the queries; null for a user's kinds. */
    val functions: PairFunctions = if kind == null then null else PairFunctions.of(kind)
