package sims.collision.narrowphase

import scala.collection.mutable.ArrayBuffer
import sims.collision.{PolyCircleCollision, PolyCollision}
import sims.collision.manifold.Manifold

/** The classic step's collision objects of the polygon kinds that no pair slot holds, handed to
  * the next slot that needs one, and the capsule kinds' scratch manifold.
  *
  * A slot gives its object back when its pair stops colliding or is of another kind (the circle
  * kind stays with its slot: in a scene of circles nearly every slot soon has one, and handing
  * them around would scatter them in memory). Contacts with polygons are often a minority that
  * moves between slots as a scene changes; kept per slot, every slot would in time allocate its own.
  */
private[sims] final class CollisionPool:
  private val sparePolyCircles = ArrayBuffer.empty[PolyCircleCollision]
  private val sparePolys = ArrayBuffer.empty[PolyCollision]

  /** The capsule kinds' manifold, filled and read at once. */
  val scratch: Manifold = Manifold()

  /** A spare polygon-circle object, or null. */
  def takePolyCircle(): PolyCircleCollision =
    if sparePolyCircles.isEmpty then null else sparePolyCircles.remove(sparePolyCircles.length - 1)

  /** A spare polygon-polygon object, or null. */
  def takePoly(): PolyCollision = if sparePolys.isEmpty then null else sparePolys.remove(sparePolys.length - 1)

  /** Gives back the slot's polygon-kind objects that its pair, of the given kind (null: a user
    * kind, or the slot holds no pair this step), does not use.
    */
  def releaseUnused(slot: PairSlot, kind: PairKind): Unit =
    if kind != PairKind.PolygonCircle && kind != PairKind.CirclePolygon then givePolyCircle(slot)
    if kind != PairKind.PolygonPolygon then givePoly(slot)

  /** Gives back the slot's polygon-circle object. */
  def givePolyCircle(slot: PairSlot): Unit =
    if slot.polyCircle != null then
      forget(slot, slot.polyCircle)
      sparePolyCircles += slot.polyCircle
      slot.polyCircle = null

  /** Gives back the slot's polygon-polygon object. */
  def givePoly(slot: PairSlot): Unit =
    if slot.poly != null then
      forget(slot, slot.poly)
      sparePolys += slot.poly
      slot.poly = null

  /** Drops the slot's last result if it is the object being given away. */
  private def forget(slot: PairSlot, c: AnyRef): Unit =
    if slot.result eq c then slot.invalidate()
