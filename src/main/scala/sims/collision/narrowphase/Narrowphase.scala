package sims.collision.narrowphase

import scala.collection.mutable.ArrayBuffer
import sims.collision.{CapsuleCollision, CircleCollision, Collision, PolyCircleCollision, PolyCollision}
import sims.collision.manifold.Manifold
import sims.dynamics.{Circle, Shape}
import sims.geometry.ConvexPolygon

/** The second stage of collision detection: for each candidate pair, whether its shapes collide
  * and their [[Collision]] (SPEC section 4).
  *
  * The detector's `detectionMethods` and `collisionMethods` lists are the extension point. They
  * fill this table: a map from a pair of shape classes to the first test and the first
  * constructor defined for it, resolved once per class pair (so a method must be defined or not
  * by the shapes' classes alone, as type patterns are) and dropped whenever a list changes.
  * When both chosen methods are the same built-in [[PairKind]], the narrowphase calls its
  * function directly and refills the pair slot's reusable collision object instead of going
  * through the partial functions, and reuses the slot's last result while neither body moved.
  */
private[sims] final class Narrowphase:
  import Narrowphase.*

  private var detectionSnapshot = Array.empty[AnyRef]
  private var collisionSnapshot = Array.empty[AnyRef]
  private val table = java.util.HashMap[(Class[?], Class[?]), Resolved]()
  // A few recent class pairs, searched by identity before the map: scenes have a handful of
  // class pairs, looked up for every candidate pair, and the map's key would be a new tuple.
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

  /** The collision of the pair in `slot` from the current positions, or null if its shapes do
    * not collide.
    */
  def collide(slot: PairSlot): Collision =
    val a = slot.first
    val b = slot.second
    val r = slot.methods
    val kind = r.kind
    if kind == null then collideGeneral(r, a, b)
    else
      val placements1 = a.body.placements
      val placements2 = b.body.placements
      if (slot.doneFirst eq a) && (slot.doneSecond eq b) && slot.donePlacements1 == placements1 &&
          slot.donePlacements2 == placements2 then
        slot.result
      else
        val c = kind match
          case PairKind.CircleCircle => circleCircle(slot, a.asInstanceOf[Circle], b.asInstanceOf[Circle])
          case PairKind.PolygonPolygon => polygonPolygon(slot, a.asInstanceOf[Polygon], b.asInstanceOf[Polygon])
          case PairKind.PolygonCircle => polygonCircle(slot, a.asInstanceOf[Polygon], b.asInstanceOf[Circle])
          case PairKind.CirclePolygon => polygonCircle(slot, b.asInstanceOf[Polygon], a.asInstanceOf[Circle])
          case PairKind.CapsuleCircle | PairKind.CapsuleCapsule | PairKind.PolygonCapsule => capsule(slot, a, b)
          case PairKind.CircleCapsule | PairKind.CapsulePolygon => capsule(slot, b, a)
        slot.doneFirst = a
        slot.doneSecond = b
        slot.donePlacements1 = placements1
        slot.donePlacements2 = placements2
        slot.result = c
        c

  private def circleCircle(slot: PairSlot, c1: Circle, c2: Circle): Collision =
    val distance = CircleCollision.centreDistance(c1, c2)
    if !(distance - (c1.radius + c2.radius) <= 0) then null
    else if slot.circle == null then { slot.circle = CircleCollision(c1, c2); slot.circle }
    else { slot.circle.compute(c1, c2, distance); slot.circle }

  private def polygonPolygon(slot: PairSlot, p1: Polygon, p2: Polygon): Collision =
    val axis = PolyCollision.referenceAxisIfColliding(p1, p2)
    if axis < 0 then { givePoly(slot); null }
    else
      if slot.poly == null then slot.poly = take(sparePolys)
      if slot.poly == null then slot.poly = PolyCollision(p1, p2)
      else slot.poly.compute(p1, p2, axis)
      slot.poly

  private def polygonCircle(slot: PairSlot, p: Polygon, c: Circle): Collision =
    if !PolyCircleCollision.colliding(p, c) then { givePolyCircle(slot); null }
    else
      if slot.polyCircle == null then slot.polyCircle = take(sparePolyCircles)
      if slot.polyCircle == null then slot.polyCircle = PolyCircleCollision(p, c)
      else slot.polyCircle.compute(p, c)
      slot.polyCircle

  /** The contact of a pair with a capsule or an edge, `reference` first (see
    * [[sims.collision.CapsuleCollision]]); each slot keeps its own object, as for circles.
    */
  private def capsule(slot: PairSlot, reference: Shape, incident: Shape): Collision =
    if slot.capsule == null then slot.capsule = CapsuleCollision.empty()
    if slot.capsule.compute(reference, incident, scratch) then slot.capsule else null

  // The capsule kinds' manifold, filled and read at once by `capsule`.
  private val scratch = Manifold()

  // Collision objects of the polygon kinds that no slot holds, handed to the next slot that
  // needs one. A slot gives its object back when its pair stops colliding or is of another kind
  // (the circle kind stays with its slot: in a scene of circles nearly every slot soon has
  // one, and handing them around would scatter them in memory). Contacts with polygons are
  // often a minority that moves between slots as a scene changes; kept per slot, every slot
  // would in time allocate its own.
  private val sparePolyCircles = ArrayBuffer.empty[PolyCircleCollision]
  private val sparePolys = ArrayBuffer.empty[PolyCollision]

  /** Gives back the slot's polygon-kind objects that its pair, of the given kind (null: a user
    * kind, or the slot holds no pair this step), does not use.
    */
  def releaseUnused(slot: PairSlot, kind: PairKind): Unit =
    if kind != PairKind.PolygonCircle && kind != PairKind.CirclePolygon then givePolyCircle(slot)
    if kind != PairKind.PolygonPolygon then givePoly(slot)

  private def givePolyCircle(slot: PairSlot): Unit =
    if slot.polyCircle != null then
      forget(slot, slot.polyCircle)
      sparePolyCircles += slot.polyCircle
      slot.polyCircle = null

  private def givePoly(slot: PairSlot): Unit =
    if slot.poly != null then
      forget(slot, slot.poly)
      sparePolys += slot.poly
      slot.poly = null

  /** A spare object, or null when there is none. */
  private def take[C <: Collision](spares: ArrayBuffer[C]): C =
    if spares.isEmpty then null.asInstanceOf[C] else spares.remove(spares.length - 1)

  /** Drops the slot's last result if it is the object being given away. */
  private def forget(slot: PairSlot, c: Collision): Unit =
    if slot.result eq c then slot.invalidate()

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
    val c1 = a.getClass
    val c2 = b.getClass
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
  private type Polygon = Shape & ConvexPolygon
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
