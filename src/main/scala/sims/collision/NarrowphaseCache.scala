package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.{Circle, Shape}
import sims.geometry.ConvexPolygon

/** Resolves the detector's partial-function lists once per pair of shape classes. The cache is
  * dropped whenever the lists change, so methods appended later are seen. When both chosen
  * methods are the same built-in kind, the narrowphase calls it directly and refills the
  * pair slot's reusable collision object instead of going through the partial functions.
  */
private[collision] final class NarrowphaseCache:
  import NarrowphaseCache.*

  private var detectionSnapshot = Array.empty[AnyRef]
  private var collisionSnapshot = Array.empty[AnyRef]
  private val resolved = java.util.HashMap[(Class[?], Class[?]), Resolved]()
  // A few recent class pairs, searched by identity before the map: scenes have a handful of
  // class pairs, looked up for every candidate pair, and the map's key would be a new tuple.
  private val recentClass1 = new Array[Class[?]](RecentSize)
  private val recentClass2 = new Array[Class[?]](RecentSize)
  private val recent = new Array[Resolved](RecentSize)
  private var recentNext = 0

  /** Drops the cache if either list changed since the last call; true if it did. */
  def update(detection: ArrayBuffer[PartialFunction[(Shape, Shape), Boolean]],
      collision: ArrayBuffer[PartialFunction[(Shape, Shape), Collision]]): Boolean =
    if !sameContents(detection, detectionSnapshot) || !sameContents(collision, collisionSnapshot) then
      detectionSnapshot = detection.toArray[AnyRef]
      collisionSnapshot = collision.toArray[AnyRef]
      resolved.clear()
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
    * not collide. Built-in kinds refill the slot's own collision object, and reuse the last
    * result when neither body has moved since it was computed (same inputs, same result).
    */
  def collide(slot: PairSlot): Collision =
    val a = slot.first
    val b = slot.second
    val r = slot.methods
    if r.kind == General then collideGeneral(r, a, b)
    else
      val moves1 = a.body.moves
      val moves2 = b.body.moves
      if (slot.doneFirst eq a) && (slot.doneSecond eq b) && slot.doneMoves1 == moves1 && slot.doneMoves2 == moves2 then
        slot.result
      else
        val c = r.kind match
          case CircleCircle =>
            val c1 = a.asInstanceOf[Circle]
            val c2 = b.asInstanceOf[Circle]
            val b1 = a.body
            val b2 = b.body
            if slot.result == null && (slot.doneFirst eq a) && (slot.doneSecond eq b) &&
                slot.doneJumps1 == b1.jumps && slot.doneJumps2 == b2.jumps &&
                (b1.travel - slot.doneTravel1) + (b2.travel - slot.doneTravel2) < slot.gap then
              // Still apart for sure: keep the last result and the reference point of the bound.
              return null
            val distance = CircleCollision.centreDistance(c1, c2)
            val separation = distance - (c1.radius + c2.radius)
            if !(separation <= 0) then
              // Apart: the gap and the travels it is measured from (read only while apart).
              slot.gap =
                if b1.centred && b2.centred then
                  separation - GapMargin * (1 + math.abs(c1.x) + math.abs(c1.y) + math.abs(c2.x) + math.abs(c2.y) + distance)
                else 0
              slot.doneTravel1 = b1.travel
              slot.doneTravel2 = b2.travel
              slot.doneJumps1 = b1.jumps
              slot.doneJumps2 = b2.jumps
              null
            else if slot.circle == null then { slot.circle = CircleCollision(c1, c2); slot.circle }
            else { slot.circle.compute(c1, c2, distance); slot.circle }
          case PolygonPolygon =>
            val p1 = a.asInstanceOf[Polygon]
            val p2 = b.asInstanceOf[Polygon]
            val axis = PolyCollision.referenceAxisIfColliding(p1, p2)
            if axis < 0 then { givePoly(slot); null }
            else
              if slot.poly == null then slot.poly = take(sparePolys)
              if slot.poly == null then slot.poly = PolyCollision(p1, p2)
              else slot.poly.compute(p1, p2, axis)
              slot.poly
          case PolygonCircle => polygonCircle(slot, a.asInstanceOf[Polygon], b.asInstanceOf[Circle])
          case _ => polygonCircle(slot, b.asInstanceOf[Polygon], a.asInstanceOf[Circle])
        slot.doneFirst = a
        slot.doneSecond = b
        slot.doneMoves1 = moves1
        slot.doneMoves2 = moves2
        slot.result = c
        c

  private def polygonCircle(slot: PairSlot, p: Polygon, c: Circle): Collision =
    if !PolyCircleCollision.colliding(p, c) then { givePolyCircle(slot); null }
    else
      if slot.polyCircle == null then slot.polyCircle = take(sparePolyCircles)
      if slot.polyCircle == null then slot.polyCircle = PolyCircleCollision(p, c)
      else slot.polyCircle.compute(p, c)
      slot.polyCircle

  // Collision objects of the polygon kinds that no slot holds, handed to the next slot that
  // needs one. A slot gives its object back when its pair stops colliding or is of another kind
  // (the circle kind stays with its slot: in a scene of circles nearly every slot soon has
  // one, and handing them around would scatter them in memory). Contacts with polygons are
  // often a minority that moves between slots as a scene changes; kept per slot, every slot
  // would in time allocate its own.
  private val sparePolyCircles = ArrayBuffer.empty[PolyCircleCollision]
  private val sparePolys = ArrayBuffer.empty[PolyCollision]

  /** Gives back the slot's polygon-kind objects that its pair, of the given kind (-1: the slot
    * holds no pair this step), does not use.
    */
  def releaseUnused(slot: PairSlot, kind: Int): Unit =
    if kind != PolygonCircle && kind != CirclePolygon then givePolyCircle(slot)
    if kind != PolygonPolygon then givePoly(slot)

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
    if slot.result eq c then
      slot.result = null
      slot.doneFirst = null
      slot.doneSecond = null

  /** A pair whose methods are not one built-in kind: through the partial functions. */
  private def collideGeneral(r: Resolved, a: Shape, b: Shape): Collision =
    val colliding = r.test match
      case t: GridDetector.BuiltIn.Test => t.direct(a, b)
      case t => t((a, b))
    if !colliding then null
    else if r.make == null then
      throw IllegalStateException(s"no collision method for a colliding pair of " +
        s"${a.getClass.getSimpleName} and ${b.getClass.getSimpleName}")
    else
      r.make match
        case m: GridDetector.BuiltIn.Make => m.direct(a, b)
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
      var r = resolved.get(key)
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
        resolved.put(key, r)
      recentClass1(recentNext) = c1
      recentClass2(recentNext) = c2
      recent(recentNext) = r
      recentNext = (recentNext + 1) % RecentSize
      r

private[collision] object NarrowphaseCache:
  private type Polygon = Shape & ConvexPolygon
  private val RecentSize = 8
  /** Rounding margin of a circle pair's gap, per unit of coordinate magnitude: far more than
    * the error of the distance and of the travel differences.
    */
  private val GapMargin = 1e-12

  /** Kinds of resolved methods: general (through the partial functions) or one built-in kind. */
  val General = 0
  val CircleCircle = 1
  val PolygonPolygon = 2
  val PolygonCircle = 3
  val CirclePolygon = 4

  /** The test and the constructor chosen for one pair of classes (either may be missing). */
  final class Resolved(val test: PartialFunction[(Shape, Shape), Boolean],
      val make: PartialFunction[(Shape, Shape), Collision]):
    /** The built-in kind when test and constructor are the same built-in kind, else General. */
    val kind: Int = (test, make) match
      case (t: GridDetector.BuiltIn.Test, m: GridDetector.BuiltIn.Make) if t.kind == m.kind => t.kind
      case _ => General
