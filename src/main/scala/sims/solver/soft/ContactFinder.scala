package sims.solver.soft

import sims.Defaults
import sims.collision.{Collision, GridDetector, PairBuffer}
import sims.collision.broadphase.UniformGrid
import sims.collision.manifold.{CapsuleCircleManifold, CapsuleManifold, CircleManifold, Manifold, PolygonCircleManifold,
  PolygonManifold}
import sims.collision.narrowphase.{Narrowphase, PairKind}
import sims.dynamics.{Circle, RoundedSegment, Shape, World}
import sims.geometry.ConvexPolygon
import sims.solver.soft.ContactTable.*

/** The soft step's collision stage, once per step (SOFTSTEP.md sections 2.1 and 4): candidate
  * pairs from bounds enlarged by the speculative distance, then a manifold of at most two
  * points with feature ids per pair, written into the table's new generation with the impulses
  * of the matching points of the last step (warm starting).
  *
  * Persistent contacts: while two bodies have moved little relative to each other since their
  * manifold was computed (see `keeps`), the manifold is kept rather than computed again: its
  * normal stays, its anchors turn with their bodies and its separations follow the bodies'
  * motion, as within the substeps. A stack's contact normals then do not tilt with every tiny
  * rotation of the boxes, which would push them sideways (without this a 12-box stack of 0.5 m
  * boxes leans and falls within 10 s), and the narrowphase is skipped for resting contacts.
  * The idea is Box2D v3.2's "contact recycling" (after PhysX's persistent manifolds).
  *
  * Pairs of the built-in kinds get the manifold functions of `sims.collision.manifold`; pairs
  * of a user's kinds go through the world's `GridDetector` lists (their `points` and `normal`,
  * the separation being minus the overlap of the shapes' projections on the normal, matched to
  * the last step's points by position). A world whose detector is not a `GridDetector` has all
  * its contacts from its detector's `collisions`, treated as user kinds.
  */
private[sims] final class ContactFinder:
  private val grid = UniformGrid()
  private val pairs = PairBuffer()
  private val narrowphase = Narrowphase()
  private val manifold = Manifold()
  private var bodies: SoftBodies = null

  /** Fills `table.current` with this step's contacts of `world`, whose bodies `bodies` holds. */
  def find(world: World, table: ContactTable, bodies: SoftBodies, speculativeDistance: Double, linearSlop: Double,
      persistence: Double): Unit =
    this.bodies = bodies
    table.begin()
    world.detector match
      case detector: GridDetector =>
        grid.gridSide = detector.gridSide
        grid.update(world.shapeBuffer, speculativeDistance)
        pairs.clear()
        grid.findPairs(pairs)
        narrowphase.update(detector.detectionMethods, detector.collisionMethods)
        var i = 0
        while i < pairs.size do
          val a = pairs.first(i)
          val b = pairs.second(i)
          val methods = narrowphase.resolve(a, b)
          val key = ContactTable.key(a, b)
          val last = table.lastOf(key)
          methods.kind match
            case null =>
              val collision = narrowphase.collideGeneral(methods, a, b)
              if collision != null then addCollision(table, collision, key, last)
            case kind =>
              if last >= 0 && persistence > 0 && keeps(table.committed, last, a, b, persistence) then keep(table, last, a, b, key)
              else
                builtIn(kind, a, b, if last >= 0 then table.committed.side(last) else -1, speculativeDistance, linearSlop)
                if manifold.pointCount > 0 then addManifold(table, a, b, key, last)
          i += 1
      case detector =>
        detector.detect()
        val collisions = detector.collisions
        var i = 0
        while i < collisions.length do
          val c = collisions(i)
          val key = ContactTable.key(c.shape1, c.shape2)
          addCollision(table, c, key, table.lastOf(key))
          i += 1

  /** Fills the manifold of a pair of built-in kinds. */
  private def builtIn(kind: PairKind, a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double): Unit =
    kind match
      case PairKind.CircleCircle =>
        CircleManifold.collide(a.asInstanceOf[Circle], b.asInstanceOf[Circle], speculativeDistance, manifold)
      case PairKind.PolygonPolygon =>
        PolygonManifold.collide(a.asInstanceOf[Polygon], b.asInstanceOf[Polygon], speculativeDistance, linearSlop, manifold)
      case PairKind.PolygonCircle =>
        PolygonCircleManifold.collide(a.asInstanceOf[Polygon], b.asInstanceOf[Circle], lastSide, speculativeDistance, manifold)
      case PairKind.CirclePolygon =>
        PolygonCircleManifold.collide(a.asInstanceOf[Circle], b.asInstanceOf[Polygon], lastSide, speculativeDistance, manifold)
      case PairKind.CapsuleCircle =>
        CapsuleCircleManifold.collide(a.asInstanceOf[RoundedSegment], b.asInstanceOf[Circle], speculativeDistance, manifold)
      case PairKind.CircleCapsule =>
        CapsuleCircleManifold.collide(a.asInstanceOf[Circle], b.asInstanceOf[RoundedSegment], speculativeDistance, manifold)
      case PairKind.CapsuleCapsule =>
        CapsuleManifold.collide(a.asInstanceOf[RoundedSegment], b.asInstanceOf[RoundedSegment], speculativeDistance,
          linearSlop, manifold)
      case PairKind.PolygonCapsule =>
        PolygonManifold.collide(a.asInstanceOf[Polygon], b.asInstanceOf[RoundedSegment], speculativeDistance, linearSlop,
          manifold)
      case PairKind.CapsulePolygon =>
        PolygonManifold.collide(a.asInstanceOf[RoundedSegment], b.asInstanceOf[Polygon], speculativeDistance, linearSlop,
          manifold)

  /** Appends the manifold of shapes (a, b) as a contact, warm started from the last step's
    * contact `last` (or -1) point by point through the feature ids.
    */
  private def addManifold(table: ContactTable, a: Shape, b: Shape, key: Long, last: Int): Unit =
    val contacts = table.current
    val c = start(contacts, a, b, key, manifold.normalX, manifold.normalY)
    contacts.side(c) = manifold.polygonSide
    contacts.pointCount(c) = manifold.pointCount
    cachePlacements(contacts, c)
    val data = contacts.data
    var p = 0
    while p < manifold.pointCount do
      val q = c * Stride + FirstPoint + p * PointStride
      setPoint(contacts, c, p, manifold.x(p), manifold.y(p), manifold.separation(p))
      data(q + CachedAnchorAX) = data(q + AnchorAX); data(q + CachedAnchorAY) = data(q + AnchorAY)
      data(q + CachedAnchorBX) = data(q + AnchorBX); data(q + CachedAnchorBY) = data(q + AnchorBY)
      data(q + CachedSeparation) = manifold.separation(p)
      contacts.ids(2 * c + p) = manifold.id(p)
      if last >= 0 then
        val old = table.committed
        var o = 0
        while o < old.pointCount(last) do
          if old.ids(2 * last + o) == manifold.id(p) then
            val r = last * Stride + FirstPoint + o * PointStride
            data(q + NormalImpulse) = old.data(r + NormalImpulse)
            data(q + TangentImpulse) = old.data(r + TangentImpulse)
          o += 1
      p += 1

  /** Whether the last step's contact `last` may be kept instead of computing the manifold
    * again: neither body turned by more than `KeepAngle` since it was computed, and the bodies'
    * relative placement changed by less than `persistence` (a shift of B in A's frame plus
    * the largest extent times the change of their relative rotation).
    */
  private def keeps(old: Contacts, last: Int, shapeA: Shape, shapeB: Shape, persistence: Double): Boolean =
    val a = shapeA.body.index
    val b = shapeB.body.index
    val k = last * Stride
    val turnA = bodies.startAngle(a) - old.data(k + CachedAngleA)
    val turnB = bodies.startAngle(b) - old.data(k + CachedAngleB)
    if math.abs(turnA) >= ContactFinder.KeepAngle || math.abs(turnB) >= ContactFinder.KeepAngle then false
    else
      // B's centre in A's frame now against then, measured in A's frame then:
      // R(-turnA) (cB - cA) - (cB - cA) then.
      val dx = bodies.startX(b) - bodies.startX(a)
      val dy = bodies.startY(b) - bodies.startY(a)
      val c = ContactFinder.cosine(turnA)
      val s = ContactFinder.sine(turnA)
      val relativeX = c * dx + s * dy - old.data(k + CachedRelativeX)
      val relativeY = -s * dx + c * dy - old.data(k + CachedRelativeY)
      val extentA = if bodies.invMass(a) == 0 then 0.0 else bodies.bodies(a).extent
      val extentB = if bodies.invMass(b) == 0 then 0.0 else bodies.bodies(b).extent
      val shift = math.sqrt(relativeX * relativeX + relativeY * relativeY)
      shift + math.max(extentA, extentB) * math.abs(ContactFinder.sine(turnB - turnA)) < persistence

  /** Appends the last step's contact `last` again: the same normal, ids and impulses, its
    * anchors turned with their bodies and its separations updated from the bodies' motion.
    */
  private def keep(table: ContactTable, last: Int, a: Shape, b: Shape, key: Long): Unit =
    val old = table.committed
    val contacts = table.current
    val k = last * Stride
    val c = start(contacts, a, b, key, old.data(k + NormalX), old.data(k + NormalY))
    contacts.side(c) = old.side(last)
    contacts.pointCount(c) = old.pointCount(last)
    val data = contacts.data
    val n = c * Stride
    data(n + CachedAngleA) = old.data(k + CachedAngleA); data(n + CachedAngleB) = old.data(k + CachedAngleB)
    data(n + CachedRelativeX) = old.data(k + CachedRelativeX); data(n + CachedRelativeY) = old.data(k + CachedRelativeY)
    val ia = contacts.bodyA(c)
    val ib = contacts.bodyB(c)
    val turnA = bodies.startAngle(ia) - old.data(k + CachedAngleA)
    val turnB = bodies.startAngle(ib) - old.data(k + CachedAngleB)
    val cA = ContactFinder.cosine(turnA); val sA = ContactFinder.sine(turnA)
    val cB = ContactFinder.cosine(turnB); val sB = ContactFinder.sine(turnB)
    val nx = data(n + NormalX); val ny = data(n + NormalY)
    var p = 0
    while p < old.pointCount(last) do
      val r = k + FirstPoint + p * PointStride
      val q = n + FirstPoint + p * PointStride
      System.arraycopy(old.data, r, data, q, PointStride)
      contacts.ids(2 * c + p) = old.ids(2 * last + p)
      val rAx = cA * old.data(r + CachedAnchorAX) - sA * old.data(r + CachedAnchorAY)
      val rAy = sA * old.data(r + CachedAnchorAX) + cA * old.data(r + CachedAnchorAY)
      val rBx = cB * old.data(r + CachedAnchorBX) - sB * old.data(r + CachedAnchorBY)
      val rBy = sB * old.data(r + CachedAnchorBX) + cB * old.data(r + CachedAnchorBY)
      // The manifold is kept whole, arms (the copied anchors) and normal as they were computed:
      // turning the arms but not the normal would couple them wrongly (measured: a 12-box stack
      // then leans and falls). Only the separation follows the bodies' motion.
      // The two anchor points coincided when the manifold was computed; their gap along n since
      // then changes the separation.
      val gapX = bodies.startX(ib) + rBx - bodies.startX(ia) - rAx
      val gapY = bodies.startY(ib) + rBy - bodies.startY(ia) - rAy
      data(q + Separation) = old.data(r + CachedSeparation) + gapX * nx + gapY * ny
      data(q + PointX) = bodies.startX(ia) + rAx
      data(q + PointY) = bodies.startY(ia) + rAy
      p += 1

  /** Sets point p of contact c at (x, y) with separation s: anchors from the bodies' centres. */
  private def setPoint(contacts: Contacts, c: Int, p: Int, x: Double, y: Double, separation: Double): Unit =
    val data = contacts.data
    val q = c * Stride + FirstPoint + p * PointStride
    val a = contacts.bodyA(c)
    val b = contacts.bodyB(c)
    data(q + PointX) = x
    data(q + PointY) = y
    data(q + AnchorAX) = x - bodies.startX(a); data(q + AnchorAY) = y - bodies.startY(a)
    data(q + AnchorBX) = x - bodies.startX(b); data(q + AnchorBY) = y - bodies.startY(b)
    data(q + Separation) = separation
    data(q + NormalImpulse) = 0
    data(q + TangentImpulse) = 0

  /** Records the bodies' placements of contact c, at which its manifold was computed. */
  private def cachePlacements(contacts: Contacts, c: Int): Unit =
    val a = contacts.bodyA(c)
    val b = contacts.bodyB(c)
    val k = c * Stride
    contacts.data(k + CachedAngleA) = bodies.startAngle(a)
    contacts.data(k + CachedAngleB) = bodies.startAngle(b)
    // cB - cA in the world frame; `keeps` turns the current one back by A's turn since.
    contacts.data(k + CachedRelativeX) = bodies.startX(b) - bodies.startX(a)
    contacts.data(k + CachedRelativeY) = bodies.startY(b) - bodies.startY(a)

  /** Appends a collision of a user kind as a contact: its normal and (at most two of) its
    * points, warm started from the last step's points within `UserMatchDistance`.
    */
  private def addCollision(table: ContactTable, collision: Collision, key: Long, last: Int): Unit =
    collision.load()
    val count = math.min(collision.pointCount, 2)
    if count > 0 then
      val contacts = table.current
      val nx = collision.normalX
      val ny = collision.normalY
      val c = start(contacts, collision.shape1, collision.shape2, key, nx, ny)
      contacts.side(c) = -1
      contacts.pointCount(c) = count
      val separation = -Collision.overlapAlong(collision.shape1, collision.shape2, nx, ny)
      val data = contacts.data
      var p = 0
      while p < count do
        val q = c * Stride + FirstPoint + p * PointStride
        val x = collision.pointX(p)
        val y = collision.pointY(p)
        setPoint(contacts, c, p, x, y, separation)
        contacts.ids(2 * c + p) = p
        if last >= 0 then
          val old = table.committed
          var o = 0
          while o < old.pointCount(last) do
            val r = last * Stride + FirstPoint + o * PointStride
            val dx = old.data(r + PointX) - x
            val dy = old.data(r + PointY) - y
            if dx * dx + dy * dy <= ContactFinder.UserMatchDistance * ContactFinder.UserMatchDistance then
              data(q + NormalImpulse) = old.data(r + NormalImpulse)
              data(q + TangentImpulse) = old.data(r + TangentImpulse)
            o += 1
        p += 1

  /** Starts contact of shapes (a, b) with normal (nx, ny) from a to b: its bodies, key and the
    * pair's friction and restitution (products of the shapes', as in the classic step).
    */
  private def start(contacts: Contacts, a: Shape, b: Shape, key: Long, nx: Double, ny: Double): Int =
    val c = contacts.add()
    contacts.shapeA(c) = a
    contacts.shapeB(c) = b
    contacts.bodyA(c) = a.body.index
    contacts.bodyB(c) = b.body.index
    contacts.keys(c) = key
    val k = c * Stride
    contacts.data(k + NormalX) = nx
    contacts.data(k + NormalY) = ny
    contacts.data(k + Friction) = a.friction * b.friction
    contacts.data(k + Restitution) = a.restitution * b.restitution
    c

private object ContactFinder:
  /** A user kind's point takes over the impulses of a last-step point this close, m. */
  val UserMatchDistance: Double = 0.01

  /** A contact is computed again once either body turned this far since, rad (cos = 0.98). */
  val KeepAngle: Double = math.acos(0.98)

  /** sin(a) for |a| < KeepAngle, to 1e-9, without the library call (Taylor to a^5). */
  inline def sine(a: Double): Double =
    val a2 = a * a
    a * (1 - a2 / 6 * (1 - a2 / 20))

  /** cos(a) for |a| < KeepAngle, to 1e-10 (Taylor to a^6). */
  inline def cosine(a: Double): Double =
    val a2 = a * a
    1 - a2 / 2 * (1 - a2 / 12 * (1 - a2 / 30))

private type Polygon = Shape & ConvexPolygon
