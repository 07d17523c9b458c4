package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.Shape

/** Resolves the detector's partial-function lists once per pair of shape classes. The cache is
  * dropped whenever the lists change, so methods appended later are seen.
  */
private[collision] final class NarrowphaseCache:
  private var detectionSnapshot = Array.empty[AnyRef]
  private var collisionSnapshot = Array.empty[AnyRef]
  private val resolved = java.util.HashMap[(Class[?], Class[?]), Resolved]()
  // One-entry memo: most scenes have one or two class pairs, looked up many times.
  private var lastClass1: Class[?] = null
  private var lastClass2: Class[?] = null
  private var last: Resolved = null

  /** The test and the constructor chosen for one pair of classes (either may be missing). */
  private final class Resolved(val test: PartialFunction[(Shape, Shape), Boolean],
      val make: PartialFunction[(Shape, Shape), Collision])

  /** Drops the cache if either list changed since the last call. */
  def update(detection: ArrayBuffer[PartialFunction[(Shape, Shape), Boolean]],
      collision: ArrayBuffer[PartialFunction[(Shape, Shape), Collision]]): Unit =
    if !sameContents(detection, detectionSnapshot) || !sameContents(collision, collisionSnapshot) then
      detectionSnapshot = detection.toArray[AnyRef]
      collisionSnapshot = collision.toArray[AnyRef]
      resolved.clear()
      lastClass1 = null
      last = null

  private def sameContents(buffer: ArrayBuffer[?], snapshot: Array[AnyRef]): Boolean =
    buffer.length == snapshot.length && buffer.indices.forall(i => buffer(i).asInstanceOf[AnyRef] eq snapshot(i))

  /** The collision of the two shapes, or null if they do not collide. */
  def collide(a: Shape, b: Shape): Collision =
    val r = resolve(a, b)
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

  private def resolve(a: Shape, b: Shape): Resolved =
    val c1 = a.getClass
    val c2 = b.getClass
    if (c1 eq lastClass1) && (c2 eq lastClass2) then last
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
      lastClass1 = c1
      lastClass2 = c2
      last = r
      r
