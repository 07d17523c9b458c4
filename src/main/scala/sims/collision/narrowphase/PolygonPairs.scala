package sims.collision.narrowphase

import sims.collision.{Collision, PolyCircleCollision, PolyCollision, ShapeSeparation}
import sims.collision.manifold.{Manifold, PolygonCircleManifold, PolygonManifold}
import sims.dynamics.{Circle, Shape}
import sims.geometry.ConvexPolygon

/** The convex polygon's entries in the narrowphase registry: polygon against polygon and
  * against circle, both ways round (its entries against capsules are the capsule's).
  */
private[sims] object PolygonPairs:
  private type Polygon = Shape & ConvexPolygon

  /** This kind's entries. */
  val entries: Seq[PairFunctions] = Seq(PolygonPolygon, PolygonCircle, CirclePolygon)

  private object PolygonPolygon extends PairFunctions(PairKind.PolygonPolygon):
    def colliding(a: Shape, b: Shape): Boolean = PolyCollision.colliding(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon])

    def collision(a: Shape, b: Shape): Collision = PolyCollision(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon])

    def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision =
      val p1 = a.asInstanceOf[Polygon]
      val p2 = b.asInstanceOf[Polygon]
      val axis = PolyCollision.referenceAxisIfColliding(p1, p2)
      if axis < 0 then { pool.givePoly(slot); null }
      else
        if slot.poly == null then slot.poly = pool.takePoly()
        if slot.poly == null then slot.poly = PolyCollision(p1, p2)
        else slot.poly.compute(p1, p2, axis)
        slot.poly

    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      PolygonManifold.collide(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon], speculativeDistance, linearSlop, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      out.polygons(a.asInstanceOf[ConvexPolygon], b.asInstanceOf[ConvexPolygon])

  private object PolygonCircle extends PairFunctions(PairKind.PolygonCircle):
    def colliding(a: Shape, b: Shape): Boolean =
      PolyCircleCollision.colliding(a.asInstanceOf[Polygon], b.asInstanceOf[Circle])

    def collision(a: Shape, b: Shape): Collision = PolyCircleCollision(a.asInstanceOf[Polygon], b.asInstanceOf[Circle])

    def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision =
      polygonCircle(slot, a.asInstanceOf[Polygon], b.asInstanceOf[Circle], pool)

    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      PolygonCircleManifold.collide(a.asInstanceOf[Polygon], b.asInstanceOf[Circle], lastSide, speculativeDistance, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      val c = b.asInstanceOf[Circle]
      out.polygonPoint(a.asInstanceOf[ConvexPolygon], c.x, c.y, c.radius)

  private object CirclePolygon extends PairFunctions(PairKind.CirclePolygon):
    def colliding(a: Shape, b: Shape): Boolean =
      PolyCircleCollision.colliding(b.asInstanceOf[Polygon], a.asInstanceOf[Circle])

    def collision(a: Shape, b: Shape): Collision = PolyCircleCollision(b.asInstanceOf[Polygon], a.asInstanceOf[Circle])

    def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision =
      polygonCircle(slot, b.asInstanceOf[Polygon], a.asInstanceOf[Circle], pool)

    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      PolygonCircleManifold.collide(a.asInstanceOf[Circle], b.asInstanceOf[Polygon], lastSide, speculativeDistance, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      val c = a.asInstanceOf[Circle]
      out.polygonPoint(b.asInstanceOf[ConvexPolygon], c.x, c.y, c.radius) && out.flip()

  /** The classic polygon-circle contact, the polygon the reference, in the slot's lent object. */
  private def polygonCircle(slot: PairSlot, p: Polygon, c: Circle, pool: CollisionPool): Collision =
    if !PolyCircleCollision.colliding(p, c) then { pool.givePolyCircle(slot); null }
    else
      if slot.polyCircle == null then slot.polyCircle = pool.takePolyCircle()
      if slot.polyCircle == null then slot.polyCircle = PolyCircleCollision(p, c)
      else slot.polyCircle.compute(p, c)
      slot.polyCircle
