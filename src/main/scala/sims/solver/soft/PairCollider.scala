package sims.solver.soft

import sims.collision.{Collision, PairBuffer, PairKey}
import sims.collision.manifold.{CircleManifold, Manifold}
import sims.collision.narrowphase.{Narrowphase, PairFunctions, PairKind, RecentMethods}
import sims.dynamics.{Circle, Shape, World}
import sims.geometry.PortableMath
import sims.solver.ShortCopy
import sims.solver.soft.ContactTable.*
import sims.solver.soft.SoftBodies.*

/** Collides pairs of shapes into a generation of contacts (`target`): each pair's manifold, or
  * the last step's kept (see `keeps`), warm started from the pair's contact of the last step.
  * The collision stage has one for its own thread and one per range of pairs when workers
  * share the pairs out: each has its own scratch, its own guess of the next last-step contact
  * and its own contacts, and reads the rest (bodies, shapes, the last step's contacts) only.
  */
private[sims] final class PairCollider:
  /** Where this step's contacts go. */
  var target: Contacts = null
  /** Whether a collider of a shared range met a pair of a user's kinds (user code need not be
    * safe to call from several threads): it stops there, and the stage collides the step's
    * pairs on its own thread instead.
    */
  var metGeneral: Boolean = false
  private val manifold = Manifold()
  private var world: World = null
  private var table: ContactTable = null
  private var bodies: SoftBodies = null
  private var timeStep, speculativeDistance, linearSlop, persistence = 0.0
  private var shared = false
  // Finds the pairs' contacts of the last step, with a guess of its own.
  private var lookup: ContactTable.Lookup = null
  // The narrowphase's methods for the last few pairs of shape classes, so that a shared range
  // takes the narrowphase's lock only for a class pair new to it in the step.
  private val recent = RecentMethods(PairCollider.RecentSize)
  // What `touch` read, summed (never used).
  private var touched = 0L

  /** Starts a step: contacts of `world`'s pairs into `target`, warm started from `table`'s
    * committed ones; `shared` when other colliders run at the same time.
    */
  def begin(world: World, table: ContactTable, bodies: SoftBodies, target: Contacts, speculativeDistance: Double,
      linearSlop: Double, persistence: Double, shared: Boolean): Unit =
    this.world = world
    this.table = table
    this.bodies = bodies
    this.target = target
    this.speculativeDistance = speculativeDistance
    this.linearSlop = linearSlop
    this.persistence = persistence
    this.shared = shared
    timeStep = world.timeStep
    metGeneral = false
    if lookup == null || lookup.table != table then lookup = ContactTable.Lookup(table)
    lookup.restart()
    // The narrowphase's methods may have changed since the last step (its `update`).
    recent.clear()

  /** The last step's contact of the pair `key`, or -1. */
  def lastOf(key: Long): Int = lookup.lastOf(key)

  // The narrowphase's methods for (a, b): its own cache on this collider's thread, else the
  // narrowphase's, under its lock when shared.
  private def resolve(a: Shape, b: Shape): Narrowphase.Resolved =
    val narrowphase = world.collisionPipeline.narrowphase
    if !shared then narrowphase.resolve(a, b)
    else
      val known = recent.find(a.shapeClass, b.shapeClass)
      if known != null then known
      else
        val resolved = narrowphase.synchronized(narrowphase.resolve(a, b))
        recent.remember(a.shapeClass, b.shapeClass, resolved)
        resolved

  /** Collides pairs `from until until` of `pairs` in order (see `collide`), each batch's shapes and
    * bodies read ahead when `readAhead` (see `touch`); a shared collider stops at a pair of a
    * user's kinds.
    */
  def collideRange(pairs: PairBuffer, from: Int, until: Int, readAhead: Boolean): Unit =
    var start = from
    while start < until && !metGeneral do
      val end = math.min(start + PairCollider.Batch, until)
      if readAhead then touch(pairs, start, end)
      var i = start
      while i < end && !metGeneral do
        collide(pairs.first(i), pairs.second(i))
        i += 1
      start = end

  // Reads, for pairs `start until end`, the shapes, bodies and body states `collide` reads first:
  // each a chain of loads (shape, its body, the body's state) that misses the cache in a large
  // world, where one pair's `collide` is too long for the processor to start the next pair's
  // loads meanwhile. In this short loop it has many pairs' misses under way at once, and the
  // batch's `collide`s find the lines in the cache (ballpit-16000: the collision stage took
  // 5.8 times ballpit-4000's for 4 times the pairs). The sum only keeps the loads from being
  // dropped as unused.
  private def touch(pairs: PairBuffer, start: Int, end: Int): Unit =
    val state = bodies.state
    var sum = 0L
    var i = start
    while i < end do
      val a = pairs.first(i).body
      val b = pairs.second(i).body
      sum += java.lang.Double.doubleToRawLongBits(state(a.index * Stride + VelocityX)) +
        java.lang.Double.doubleToRawLongBits(state(b.index * Stride + VelocityX)) +
        (if a.allCentred && b.allCentred then 1 else 0)
      i += 1
    touched = sum

  /** Collides the pair (a, b): its manifold (or the last step's, kept), as a contact of this step. */
  def collide(a: Shape, b: Shape): Unit =
    val methods = resolve(a, b)
    val functions = methods.functions
    if functions == null && shared then
      metGeneral = true
      return
    val key = PairKey.of(a, b)
    val last = lastOf(key)
    val circles = PairCollider.centredCircles(functions, a, b)
    // For every pair, kept or not: it also refuses speeds too large to compute with.
    val approach = approachBound(a.body.index, b.body.index, circles)
    if functions == null then
      val collision = world.collisionPipeline.narrowphase.collideGeneral(methods, a, b)
      if collision != null then addCollision(collision, key, last)
    else if last >= 0 && persistence > 0 && functions.kind != PairKind.CircleCircle &&
      keeps(table.committed, last, a, b) then
      keep(last, a, b, key, functions)
    else if circles == Turnless then // two circles on their bodies' centres
      val circleA = a.asInstanceOf[Circle]
      val circleB = b.asInstanceOf[Circle]
      CircleManifold.collide(circleA, circleB, speculativeDistance + timeStep * approach, manifold)
      if manifold.pointCount > 0 then addCircles(circleA, circleB, key, last)
    else
      functions.manifold(a, b, if last >= 0 then table.committed.side(last) else -1,
        speculativeDistance + timeStep * approach, linearSlop, manifold)
      if manifold.pointCount > 0 then addManifold(a, b, key, last, PairCollider.turnless(circles, a, b))

  /** Whether shapes a and b touch as the soft step counts it: their manifold has a point. */
  def touches(a: Shape, b: Shape): Boolean =
    val narrowphase = world.collisionPipeline.narrowphase
    val methods = resolve(a, b)
    val functions = methods.functions
    val approach = approachBound(a.body.index, b.body.index, PairCollider.centredCircles(functions, a, b))
    if functions == null then narrowphase.collideGeneral(methods, a, b) != null
    else
      functions.manifold(a, b, -1, speculativeDistance + timeStep * approach, linearSlop, manifold)
      manifold.pointCount > 0

  /** Appends the last step's contact `last` of a pair asleep as it is (its bodies' indices as
    * they are now): its impulses warm start the pair when its island wakes.
    */
  def carry(last: Int, a: Shape, b: Shape, key: Long): Unit =
    val old = table.committed
    val contacts = target
    val points = old.pointCount(last)
    val k = old.offset(last)
    val c = start(contacts, a, b, key, old.hot(k + NormalX), old.hot(k + NormalY), points, -1, old.turnless(last))
    contacts.side(c) = old.side(last)
    ShortCopy.doubles(old.hot, k, contacts.hot, contacts.offset(c), Header + points * HotPoint)
    ShortCopy.doubles(old.cold, old.coldOffset(last), contacts.cold, contacts.coldOffset(c), ColdStride)
    ShortCopy.doubles(old.records, last * RecordStride, contacts.records, c * RecordStride, RecordStride)
    // Asleep, the pair is not prepared again: its softness may be of settings changed since.
    contacts.records(c * RecordStride + Stiffened) = 0
    contacts.ids(2 * c) = old.ids(2 * last)
    contacts.ids(2 * c + 1) = old.ids(2 * last + 1)

  /** An upper bound of how fast two bodies' shapes can approach each other at the start of
    * the step: |vA - vB| + |wA| extentA + |wB| extentB, without the spin of a side that is a
    * circle on its body's centre (`circles`, [[centredCircles]]' bits: its turn moves no point of
    * its outline towards the other shape). Over the step they close at most this times the time
    * step, so points that far apart are speculative points: a fast ball is caught where it would
    * land instead of sinking deep into a pile within one step (and being pushed out of it at
    * speed).
    */
  private def approachBound(a: Int, b: Int, circles: Int): Double =
    val state = bodies.state
    val sA = a * SoftBodies.Stride
    val sB = b * SoftBodies.Stride
    val dvx = state(sB + VelocityX) - state(sA + VelocityX)
    val dvy = state(sB + VelocityY) - state(sA + VelocityY)
    var bound = math.sqrt(dvx * dvx + dvy * dvy)
    if (circles & TurnlessA) == 0 then bound += math.abs(state(sA + AngularVelocity)) * bodies.bodies(a).extent
    if (circles & TurnlessB) == 0 then bound += math.abs(state(sB + AngularVelocity)) * bodies.bodies(b).extent
    // Its square overflows from 1.3e154 m/s on: speeds at which the contacts' products (a
    // speed times an arm, a mass, an inverse inertia) overflow or lose all meaning.
    if !java.lang.Double.isFinite(bound * bound) then overflow(a, b, bound)
    bound

  /** A pair approaching too fast to compute with (a finite velocity near Double.MaxValue: the
    * step would carry on with positions of 1e306 m, or spread NaN to the other body): an error
    * naming the faster body. The world restores its state before the step and names the stage.
    */
  private def overflow(a: Int, b: Int, bound: Double): Nothing =
    // The bodies still hold their velocities of the start of the step.
    def speed(i: Int): Double =
      val body = bodies.bodies(i)
      math.abs(body.vx) + math.abs(body.vy) + math.abs(body.w) * body.extent
    val (fast, other) = if speed(a) >= speed(b) then (a, b) else (b, a)
    val body = bodies.bodies(fast)
    throw ArithmeticException(s"the speed of body $fast ($body: velocity ${body.linearVelocity}, angular velocity " +
      s"${body.angularVelocity}) is too large to compute its pair with body $other (approach bound $bound m/s)")

  /** Appends the manifold of shapes (a, b) as a contact, warm started from the last step's
    * contact `last` (or -1) point by point through the feature ids.
    */
  private def addManifold(a: Shape, b: Shape, key: Long, last: Int, turnless: Int): Unit =
    val contacts = target
    val c = start(contacts, a, b, key, manifold.normalX, manifold.normalY, manifold.pointCount, last, turnless)
    contacts.side(c) = manifold.polygonSide
    cachePlacements(contacts, c)
    var p = 0
    while p < manifold.pointCount do
      setPoint(contacts, c, p, manifold.x(p), manifold.y(p), manifold.separation(p))
      cacheAnchors(contacts, c, p)
      contacts.ids(2 * c + p) = manifold.id(p)
      warmStartPoint(contacts, c, p, last)
      p += 1

  /** `addManifold` for two circles on their bodies' centres (one point, id 0), turned to the
    * normal they meet along if they are apart and approaching (see `aimAtImpact`): each slot
    * written once. A pair of circles is never kept (see `collide`), so nothing is cached for
    * `keeps`: the most common contact of a pile of balls, and the cheapest.
    */
  private def addCircles(circleA: Circle, circleB: Circle, key: Long, last: Int): Unit =
    val contacts = target
    val c = start(contacts, circleA, circleB, key, manifold.normalX, manifold.normalY, 1, last, Turnless)
    contacts.side(c) = Uncached
    if !aimAtImpact(contacts, c, circleA, circleB) then
      setPoint(contacts, c, 0, manifold.x(0), manifold.y(0), manifold.separation(0))
    contacts.ids(2 * c) = manifold.id(0)
    warmStartPoint(contacts, c, 0, last)

  /** Point p of contact c as computed: its anchors and separation, which `keeps` compares with. */
  private def cacheAnchors(contacts: Contacts, c: Int, p: Int): Unit =
    val hot = contacts.hot
    val cold = contacts.cold
    val q = contacts.hotPoint(c, p)
    val r = contacts.coldPoint(c, p)
    cold(r + CachedAnchorAX) = hot(q + AnchorAX); cold(r + CachedAnchorAY) = hot(q + AnchorAY)
    cold(r + CachedAnchorBX) = hot(q + AnchorBX); cold(r + CachedAnchorBY) = hot(q + AnchorBY)
    cold(r + CachedSeparation) = cold(r + Separation)

  /** The impulses of point p of contact c from the point of the last step's contact `last` (if
    * any) with its feature id.
    */
  private def warmStartPoint(contacts: Contacts, c: Int, p: Int, last: Int): Unit =
    if last >= 0 then
      val id = contacts.ids(2 * c + p)
      val old = table.committed
      val q = contacts.hotPoint(c, p)
      var o = 0
      while o < old.pointCount(last) do
        if old.ids(2 * last + o) == id then
          val from = old.hotPoint(last, o)
          contacts.hot(q + NormalImpulse) = old.hot(from + NormalImpulse)
          contacts.hot(q + TangentImpulse) = old.hot(from + TangentImpulse)
        o += 1

  /** Writes the point of contact c of two circles on their bodies' centres turned to the normal
    * they meet along, if they are apart and approaching: the line of their centres when, moving
    * as at the start of the step, they first touch, or when they come closest within the step if
    * they pass each other. Its arms then lie along that normal, from each centre to the outline,
    * its separation is the gap along it, its impulses 0. Returns whether it did; otherwise (the
    * circles touch already, or move apart) the manifold's point, along the line of centres at the
    * start, stands.
    *
    * Why: the contact keeps its normal for the whole step, and a contact found before the balls
    * touch (speculative, up to a step ahead) has the line of centres of the start, which for two
    * balls glancing past each other is far from the line at impact: the impulses then push
    * along a line that misses the centres at impact (a couple that changes the angular
    * momentum, and a rebound in the wrong direction), and the gap along the start's normal
    * closes before the balls touch. Along the line at impact the collision is as between real
    * balls; along the line of closest approach the gap never closes early.
    */
  private def aimAtImpact(contacts: Contacts, c: Int, circleA: Circle, circleB: Circle): Boolean =
    val a = contacts.bodyA(c)
    val b = contacts.bodyB(c)
    val dx = bodies.startX(b) - bodies.startX(a)
    val dy = bodies.startY(b) - bodies.startY(a)
    val sA = a * Stride; val sB = b * Stride
    val vx = bodies.state(sB + VelocityX) - bodies.state(sA + VelocityX)
    val vy = bodies.state(sB + VelocityY) - bodies.state(sA + VelocityY)
    val reach = circleA.radius + circleB.radius
    // |d + t v| = reach: speed2 t^2 + 2 half t + gap = 0.
    val speed2 = vx * vx + vy * vy
    val half = dx * vx + dy * vy
    val gap = dx * dx + dy * dy - reach * reach
    if gap > 0 && half < 0 then // apart and approaching
      val discriminant = half * half - speed2 * gap
      // The impact, however far ahead (then the gap along its line stays open all step, and a
      // push at the step's end, which a contact about to close makes, bounces along it), or
      // the closest approach within the step for balls that pass each other.
      val t = if discriminant >= 0 then (-half - math.sqrt(discriminant)) / speed2 else math.min(-half / speed2, timeStep)
      val hot = contacts.hot
      val k = contacts.offset(c)
      val ix = dx + t * vx; val iy = dy + t * vy
      val length = math.sqrt(ix * ix + iy * iy)
      val nx = ix / length; val ny = iy / length
      val cold = contacts.cold
      hot(k + NormalX) = nx; hot(k + NormalY) = ny
      val q = contacts.hotPoint(c, 0)
      val r = contacts.coldPoint(c, 0)
      hot(q + AnchorAX) = circleA.radius * nx; hot(q + AnchorAY) = circleA.radius * ny
      hot(q + AnchorBX) = -circleB.radius * nx; hot(q + AnchorBY) = -circleB.radius * ny
      hot(q + NormalImpulse) = 0
      hot(q + TangentImpulse) = 0
      cold(r + PointX) = bodies.startX(a) + hot(q + AnchorAX)
      cold(r + PointY) = bodies.startY(a) + hot(q + AnchorAY)
      cold(r + Separation) = dx * nx + dy * ny - reach
      true
    else false

  /** Whether the last step's contact `last` may be kept instead of computing the manifold
    * again: neither body turned by more than `KeepAngle` since it was computed, and the bodies'
    * relative placement changed by less than `persistence` (a shift of B in A's frame plus
    * the largest extent times the change of their relative rotation).
    */
  private def keeps(old: Contacts, last: Int, shapeA: Shape, shapeB: Shape): Boolean =
    val a = shapeA.body.index
    val b = shapeB.body.index
    val k = old.coldOffset(last)
    val turnA = bodies.startAngle(a) - old.cold(k + CachedAngleA)
    val turnB = bodies.startAngle(b) - old.cold(k + CachedAngleB)
    if math.abs(turnA) >= PairCollider.KeepAngle || math.abs(turnB) >= PairCollider.KeepAngle then false
    else
      // B's centre in A's frame now against then, measured in A's frame then:
      // R(-turnA) (cB - cA) - (cB - cA) then.
      val dx = bodies.startX(b) - bodies.startX(a)
      val dy = bodies.startY(b) - bodies.startY(a)
      val c = PairCollider.cosine(turnA)
      val s = PairCollider.sine(turnA)
      val relativeX = c * dx + s * dy - old.cold(k + CachedRelativeX)
      val relativeY = -s * dx + c * dy - old.cold(k + CachedRelativeY)
      val extentA = if bodies.bodies(a).fixed then 0.0 else bodies.bodies(a).extent
      val extentB = if bodies.bodies(b).fixed then 0.0 else bodies.bodies(b).extent
      val shift = math.sqrt(relativeX * relativeX + relativeY * relativeY)
      shift + math.max(extentA, extentB) * math.abs(PairCollider.sine(turnB - turnA)) < persistence

  /** Appends the last step's contact `last` again: the same normal, ids and impulses, its
    * separations updated from the bodies' motion.
    */
  private def keep(last: Int, a: Shape, b: Shape, key: Long, functions: PairFunctions): Unit =
    val circles = PairCollider.centredCircles(functions, a, b)
    val old = table.committed
    val contacts = target
    val points = old.pointCount(last)
    val k = old.offset(last)
    val c = start(contacts, a, b, key, old.hot(k + NormalX), old.hot(k + NormalY), points, last,
      PairCollider.turnless(circles, a, b))
    contacts.side(c) = old.side(last)
    val hot = contacts.hot
    val cold = contacts.cold
    val oldCold = old.coldOffset(last)
    ShortCopy.doubles(old.cold, oldCold, cold, contacts.coldOffset(c), ColdStride)
    val ia = contacts.bodyA(c)
    val ib = contacts.bodyB(c)
    val turnA = bodies.startAngle(ia) - old.cold(oldCold + CachedAngleA)
    val turnB = bodies.startAngle(ib) - old.cold(oldCold + CachedAngleB)
    // A circle's arm is not turned: its outline stays where it was along the normal. (A fixed
    // body's is: the user may have turned it since.)
    val turnsA = (circles & TurnlessA) == 0
    val turnsB = (circles & TurnlessB) == 0
    val cA = if turnsA then PairCollider.cosine(turnA) else 1.0; val sA = if turnsA then PairCollider.sine(turnA) else 0.0
    val cB = if turnsB then PairCollider.cosine(turnB) else 1.0; val sB = if turnsB then PairCollider.sine(turnB) else 0.0
    val nx = old.hot(k + NormalX); val ny = old.hot(k + NormalY)
    var p = 0
    while p < points do
      val from = old.hotPoint(last, p)
      val q = contacts.hotPoint(c, p)
      val r = contacts.coldPoint(c, p)
      contacts.ids(2 * c + p) = old.ids(2 * last + p)
      hot(q + NormalImpulse) = old.hot(from + NormalImpulse)
      hot(q + TangentImpulse) = old.hot(from + TangentImpulse)
      val anchorAX = cold(r + CachedAnchorAX); val anchorAY = cold(r + CachedAnchorAY)
      val anchorBX = cold(r + CachedAnchorBX); val anchorBY = cold(r + CachedAnchorBY)
      // The impulses act where the manifold put them (its anchors), not turned: the manifold
      // is kept whole, arms and normal as computed. Turning the arms but not the normal couples
      // them wrongly (measured: a 12-box stack then leans and falls within 10 s; so does acting
      // at the middle of the two anchor points). The price: once the anchor points have slid
      // apart along the surface, the two impulses form a small couple, and angular momentum is
      // no longer exact (measured: 4e-4 of it over 2 s in a tumbling free pair).
      hot(q + AnchorAX) = anchorAX; hot(q + AnchorAY) = anchorAY
      hot(q + AnchorBX) = anchorBX; hot(q + AnchorBY) = anchorBY
      // The two anchor points coincided when the manifold was computed; their gap along n
      // since then, with the arms turned with their bodies, changes the separation.
      val rAx = cA * anchorAX - sA * anchorAY
      val rAy = sA * anchorAX + cA * anchorAY
      val rBx = cB * anchorBX - sB * anchorBY
      val rBy = sB * anchorBX + cB * anchorBY
      val gapX = bodies.startX(ib) + rBx - bodies.startX(ia) - rAx
      val gapY = bodies.startY(ib) + rBy - bodies.startY(ia) - rAy
      cold(r + Separation) = cold(r + CachedSeparation) + gapX * nx + gapY * ny
      cold(r + PointX) = bodies.startX(ia) + rAx
      cold(r + PointY) = bodies.startY(ia) + rAy
      p += 1

  /** Sets point p of contact c at (x, y) with separation s: anchors from the bodies' centres,
    * no impulses yet.
    */
  private def setPoint(contacts: Contacts, c: Int, p: Int, x: Double, y: Double, separation: Double): Unit =
    val q = contacts.hotPoint(c, p)
    val r = contacts.coldPoint(c, p)
    val a = contacts.bodyA(c)
    val b = contacts.bodyB(c)
    val hot = contacts.hot
    hot(q + AnchorAX) = x - bodies.startX(a); hot(q + AnchorAY) = y - bodies.startY(a)
    hot(q + AnchorBX) = x - bodies.startX(b); hot(q + AnchorBY) = y - bodies.startY(b)
    hot(q + NormalImpulse) = 0
    hot(q + TangentImpulse) = 0
    contacts.cold(r + PointX) = x
    contacts.cold(r + PointY) = y
    contacts.cold(r + Separation) = separation

  /** Records the bodies' placements of contact c, at which its manifold was computed. */
  private def cachePlacements(contacts: Contacts, c: Int): Unit =
    val a = contacts.bodyA(c)
    val b = contacts.bodyB(c)
    val k = contacts.coldOffset(c)
    contacts.cold(k + CachedAngleA) = bodies.startAngle(a)
    contacts.cold(k + CachedAngleB) = bodies.startAngle(b)
    // cB - cA in the world frame; `keeps` turns the current one back by A's turn since.
    contacts.cold(k + CachedRelativeX) = bodies.startX(b) - bodies.startX(a)
    contacts.cold(k + CachedRelativeY) = bodies.startY(b) - bodies.startY(a)

  /** Appends a collision of a user kind as a contact: its normal and (at most two of) its
    * points, warm started from the last step's points within `UserMatchDistance`.
    */
  def addCollision(collision: Collision, key: Long, last: Int): Unit =
    collision.load()
    val count = math.min(collision.pointCount, 2)
    if count > 0 then
      val contacts = target
      val nx = collision.normalX
      val ny = collision.normalY
      val c = start(contacts, collision.shape1, collision.shape2, key, nx, ny, count, last,
        PairCollider.turnless(null, collision.shape1, collision.shape2))
      contacts.side(c) = -1
      val separation = -Collision.overlapAlong(collision.shape1, collision.shape2, nx, ny)
      var p = 0
      while p < count do
        val x = collision.pointX(p)
        val y = collision.pointY(p)
        setPoint(contacts, c, p, x, y, separation)
        contacts.ids(2 * c + p) = p
        if last >= 0 then
          val old = table.committed
          var o = 0
          while o < old.pointCount(last) do
            val r = old.coldPoint(last, o)
            val dx = old.cold(r + PointX) - x
            val dy = old.cold(r + PointY) - y
            if dx * dx + dy * dy <= PairCollider.UserMatchDistance * PairCollider.UserMatchDistance then
              val from = old.hotPoint(last, o)
              val q = contacts.hotPoint(c, p)
              contacts.hot(q + NormalImpulse) = old.hot(from + NormalImpulse)
              contacts.hot(q + TangentImpulse) = old.hot(from + TangentImpulse)
            o += 1
        p += 1

  /** Starts contact of shapes (a, b) with normal (nx, ny) from a to b and `points` points: its
    * bodies, key and the pair's friction and restitution (products of the shapes', as in the
    * classic step), and from the pair's last contact `last` (if any) its stiffness and softness
    * (see [[ContactStiffness]]).
    */
  private def start(contacts: Contacts, a: Shape, b: Shape, key: Long, nx: Double, ny: Double, points: Int,
      last: Int, turnless: Int): Int =
    val c = contacts.add(points)
    // Storing a reference costs the garbage collector's write barrier, and the slot usually holds
    // these shapes already: a generation's slots are reused every other step, in much the same order.
    if contacts.shapeA(c) ne a then contacts.shapeA(c) = a
    if contacts.shapeB(c) ne b then contacts.shapeB(c) = b
    contacts.bodyA(c) = a.body.index
    contacts.bodyB(c) = b.body.index
    contacts.keys(c) = key
    contacts.reportsEvents(c) = a.enableContactEvents && b.enableContactEvents
    // Both sides turnless only for one point (two fixed bodies never meet).
    contacts.turnless(c) = (if turnless == Turnless && points != 1 then 0 else turnless).toByte
    val k = contacts.offset(c)
    contacts.hot(k + NormalX) = nx
    contacts.hot(k + NormalY) = ny
    contacts.hot(k + Friction) = a.friction * b.friction
    val restitution = a.restitution * b.restitution
    contacts.records(c * RecordStride + Restitution) = restitution
    if restitution != 0 then contacts.bouncing = true
    val record = c * RecordStride
    if last < 0 then
      contacts.records(record + Stiffness) = 0
      contacts.records(record + Stiffened) = 0
    else
      val old = table.committed
      val stiffened = old.records(last * RecordStride + Stiffened)
      contacts.records(record + Stiffness) = old.records(last * RecordStride + Stiffness)
      contacts.records(record + Stiffened) = stiffened
      // The softness that goes with it; a contact of the plain softness gets it in `prepare`.
      if stiffened != 0 then
        val from = old.offset(last)
        contacts.hot(k + BiasRate) = old.hot(from + BiasRate)
        contacts.hot(k + MassScale) = old.hot(from + MassScale)
        contacts.hot(k + ImpulseScale) = old.hot(from + ImpulseScale)
    c

private[sims] object PairCollider:
  /** The turnless sides ([[ContactTable.TurnlessA]], [[ContactTable.TurnlessB]]) of a contact of
    * shapes a and b made by the narrowphase's `functions` for them (null: a user's kind, whose
    * points may lie anywhere): a circle of a built-in kind on its body's centre, or a fixed body.
    */
  def turnless(functions: PairFunctions, a: Shape, b: Shape): Int = turnless(centredCircles(functions, a, b), a, b)

  /** [[turnless]] from the pair's `centredCircles`. */
  def turnless(circles: Int, a: Shape, b: Shape): Int =
    // A fixed side only counts opposite a circle: what the short way needs. Elsewhere its turn,
    // 0 within a step, needs no mark, and the general row's common case stays unmarked.
    if circles == TurnlessA && b.body.fixed || circles == TurnlessB && a.body.fixed then Turnless else circles

  /** The sides of a contact of shapes a and b made by `functions` that are circles of a built-in
    * kind on their bodies' centres, as [[turnless]]'s bits.
    */
  def centredCircles(functions: PairFunctions, a: Shape, b: Shape): Int =
    val sides = if functions == null then 0 else functions.kind.circleSides
    if sides == 0 then 0
    else
      (if (sides & 1) != 0 && a.body.allCentred then TurnlessA else 0) |
        (if (sides & 2) != 0 && b.body.allCentred then TurnlessB else 0)

  /** Pairs whose shapes and bodies `collideRange` reads ahead at once. */
  inline val Batch = 64

  /** The fewest pairs in a step for which the collision stage reads ahead: fewer sit in the caches,
    * where the loop only costs (measured: ballpit-16000's 52,000 pairs 2 to 8% faster with it; ballpit-500's
    * 1,500 2.5 to 4% slower, ballpit-4000's 12,000 and large_pyramid's 15,000 1 to 3% slower).
    */
  inline val ReadAheadPairs = 16384

  /** Class pairs a shared collider remembers. */
  inline val RecentSize = 4

  /** A user kind's point takes over the impulses of a last-step point this close, m. */
  val UserMatchDistance: Double = 0.01

  /** A contact is computed again once either body turned this far since, rad (cos = 0.98). */
  val KeepAngle: Double = PortableMath.acos(0.98)

  /** sin(a) for |a| < KeepAngle, to 1e-9, without the library call (Taylor to a^5; its
    * coefficients multiply: a division by a constant stays a division, several times as slow).
    */
  inline def sine(a: Double): Double =
    val a2 = a * a
    a * (1 - a2 * (Sixth - a2 * OneOver120))

  /** cos(a) for |a| < KeepAngle, to 1e-10 (Taylor to a^6). */
  inline def cosine(a: Double): Double =
    val a2 = a * a
    1 - a2 * (0.5 - a2 * (OneOver24 - a2 * OneOver720))

  private inline val Sixth = 1.0 / 6
  private inline val OneOver24 = 1.0 / 24
  private inline val OneOver120 = 1.0 / 120
  private inline val OneOver720 = 1.0 / 720
