package sims.solver.soft

import sims.collision.{Collision, GridDetector, PairKey}
import sims.collision.manifold.Manifold
import sims.collision.narrowphase.PairKind
import sims.dynamics.{Circle, Shape, World}
import sims.geometry.PortableMath
import sims.solver.ShortCopy
import sims.solver.soft.ContactTable.*
import sims.solver.soft.SoftBodies.*

/** The soft step's collision stage, once per step (see docs/two-solvers.md): candidate
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
  * The idea is Box2D v3.2's "contact recycling" (after PhysX's persistent manifolds). Pairs of
  * circles are computed every step: their normal is the line of their centres whatever their
  * rotation, so keeping it gains no stability, and its anchors, kept while the balls roll
  * past each other, slide apart: the two impulses then form a couple, which changed the
  * angular momentum of 60 balls colliding in free space by 1.5% in 10 s (0.4% without).
  *
  * Pairs of the built-in kinds get their manifold from the narrowphase registry's entry
  * ([[sims.collision.narrowphase.PairFunctions]]); pairs
  * of a user's kinds go through the world's `GridDetector` lists (their `points` and `normal`,
  * the separation being minus the overlap of the shapes' projections on the normal, matched to
  * the last step's points by position). A world whose detector is not a `GridDetector` has all
  * its contacts from its detector's `collisions`, treated as user kinds.
  */
private[sims] final class ContactFinder:
  private val manifold = Manifold()
  private var bodies: SoftBodies = null
  private var world: World = null
  private var timeStep = 0.0

  /** Fills `table.current` with this step's contacts of `world`, whose bodies `bodies` holds,
    * with the world's broadphase in cells of `gridSide` and at most `maxPairs` candidate pairs.
    */
  def find(world: World, table: ContactTable, bodies: SoftBodies, gridSide: Double, maxPairs: Int,
      speculativeDistance: Double, linearSlop: Double, persistence: Double): Unit =
    this.bodies = bodies
    this.world = world
    timeStep = world.timeStep
    table.begin()
    if bodies.anyAsleep then wakeOnMovedFixed(table.committed)
    world.detector match
      case detector: GridDetector =>
        val stages = world.collisionPipeline
        stages.findPairs(world.shapeBuffer, gridSide, maxPairs, "SoftStep.maxPairs", speculativeDistance, timeStep,
          inGridOrder = false)
        val pairs = stages.pairs
        val narrowphase = stages.narrowphase
        narrowphase.update(detector.detectionMethods, detector.collisionMethods)
        if !bodies.anyAsleep then
          var i = 0
          while i < pairs.size do
            collide(table, pairs.first(i), pairs.second(i), speculativeDistance, linearSlop, persistence)
            i += 1
        else
          // Sleeping islands touched by an awake body (or by a fixed body the user moved) wake
          // first, and the islands they touch in turn; then the pairs with a moving body are
          // collided, and the contacts of pairs still asleep are carried over unchanged, after
          // them (the passes solve only the first `active`).
          var woke = true
          while woke do
            woke = false
            var i = 0
            while i < pairs.size do
              val a = pairs.first(i)
              val b = pairs.second(i)
              val ia = a.body.index
              val ib = b.body.index
              val sleeper = if bodies.asleep(ia) && wakes(ib) then ia else if bodies.asleep(ib) && wakes(ia) then ib else -1
              if sleeper >= 0 && touches(a, b, speculativeDistance, linearSlop) then
                bodies.wakeIsland(bodies.bodies(sleeper).sleepIsland)
                woke = true
              i += 1
          var i = 0
          while i < pairs.size do
            val a = pairs.first(i)
            val b = pairs.second(i)
            if bodies.invMass(a.body.index) != 0 || bodies.invMass(b.body.index) != 0 then
              collide(table, a, b, speculativeDistance, linearSlop, persistence)
            i += 1
          table.current.active = table.current.count
          i = 0
          while i < pairs.size do
            val a = pairs.first(i)
            val b = pairs.second(i)
            if bodies.invMass(a.body.index) == 0 && bodies.invMass(b.body.index) == 0 then
              val key = PairKey.of(a, b)
              val last = table.lastOf(key)
              if last >= 0 then carry(table, last, a, b, key)
              // A pair asleep with no contact kept (the last step did not look for contacts, or
              // the user put the bodies to sleep): its manifold now, to warm-start from 0.
              else collide(table, a, b, speculativeDistance, linearSlop, persistence)
            i += 1
      case detector =>
        detector.detect()
        val collisions = detector.collisions
        // A detector of the user's finds every colliding pair: a sleeper colliding with a body
        // that wakes it wakes, and the islands it touches in turn.
        var woke = bodies.anyAsleep
        while woke do
          woke = false
          var i = 0
          while i < collisions.length do
            val ia = collisions(i).shape1.body.index
            val ib = collisions(i).shape2.body.index
            val sleeper = if bodies.asleep(ia) && wakes(ib) then ia else if bodies.asleep(ib) && wakes(ia) then ib else -1
            if sleeper >= 0 then
              bodies.wakeIsland(bodies.bodies(sleeper).sleepIsland)
              woke = true
            i += 1
        var i = 0
        while i < collisions.length do
          val c = collisions(i)
          val key = PairKey.of(c.shape1, c.shape2)
          addCollision(table, c, key, table.lastOf(key))
          i += 1
    if !bodies.anyAsleep || !world.detector.isInstanceOf[GridDetector] then table.current.active = table.current.count

  /** Collides the pair (a, b): its manifold (or the last step's, kept), as a contact of this step. */
  private def collide(table: ContactTable, a: Shape, b: Shape, speculativeDistance: Double, linearSlop: Double,
      persistence: Double): Unit =
    val stages = world.collisionPipeline
    val narrowphase = stages.narrowphase
    val methods = narrowphase.resolve(a, b)
    val key = PairKey.of(a, b)
    val last = table.lastOf(key)
    // For every pair, kept or not: it also refuses speeds too large to compute with.
    val approach = approachBound(a.body.index, b.body.index)
    val functions = methods.functions
    if functions == null then
      val collision = narrowphase.collideGeneral(methods, a, b)
      if collision != null then addCollision(table, collision, key, last)
    else if last >= 0 && persistence > 0 && functions.kind != PairKind.CircleCircle &&
      keeps(table.committed, last, a, b, persistence) then
      keep(table, last, a, b, key)
    else
      functions.manifold(a, b, if last >= 0 then table.committed.side(last) else -1,
        speculativeDistance + timeStep * approach, linearSlop, manifold)
      if manifold.pointCount > 0 then
        addManifold(table, a, b, key, last)
        if functions.kind == PairKind.CircleCircle && a.body.allCentred && b.body.allCentred then
          aimAtImpact(table.current, table.current.count - 1, a.asInstanceOf[Circle], b.asInstanceOf[Circle])

  /** Wakes the sleeping islands that touched, at the last step, a fixed body the user placed
    * since: it may have moved away from them (they would hang in the air) or into them.
    */
  private def wakeOnMovedFixed(committed: Contacts): Unit =
    var c = 0
    while c < committed.count do
      val a = committed.shapeA(c).body.index
      val b = committed.shapeB(c).body.index
      if a >= 0 && b >= 0 then
        if bodies.asleep(a) && !bodies.asleep(b) && bodies.bodies(b).movedByUser then
          bodies.wakeIsland(bodies.bodies(a).sleepIsland)
        else if bodies.asleep(b) && !bodies.asleep(a) && bodies.bodies(a).movedByUser then
          bodies.wakeIsland(bodies.bodies(b).sleepIsland)
      c += 1

  /** Whether body i wakes a sleeping body it touches: it moves (awake and not fixed, or
    * kinematic with a velocity), or it is a fixed body the user placed since the last step.
    */
  private def wakes(i: Int): Boolean =
    if bodies.invMass(i) != 0 then true
    else
      val body = bodies.bodies(i)
      body.movesItself || (!bodies.asleep(i) && body.movedByUser)

  /** Whether shapes a and b touch as the soft step counts it: their manifold has a point. */
  private def touches(a: Shape, b: Shape, speculativeDistance: Double, linearSlop: Double): Boolean =
    val narrowphase = world.collisionPipeline.narrowphase
    val methods = narrowphase.resolve(a, b)
    val approach = approachBound(a.body.index, b.body.index)
    val functions = methods.functions
    if functions == null then narrowphase.collideGeneral(methods, a, b) != null
    else
      functions.manifold(a, b, -1, speculativeDistance + timeStep * approach, linearSlop, manifold)
      manifold.pointCount > 0

  /** Appends the last step's contact `last` of a pair asleep as it is (its bodies' indices as
    * they are now): its impulses warm start the pair when its island wakes.
    */
  private def carry(table: ContactTable, last: Int, a: Shape, b: Shape, key: Long): Unit =
    val old = table.committed
    val contacts = table.current
    val points = old.pointCount(last)
    val k = old.offset(last)
    val c = start(contacts, a, b, key, old.hot(k + NormalX), old.hot(k + NormalY), points, 0.0)
    contacts.side(c) = old.side(last)
    ShortCopy.doubles(old.hot, k, contacts.hot, contacts.offset(c), Header + points * HotPoint)
    ShortCopy.doubles(old.cold, last * ColdStride, contacts.cold, c * ColdStride, ColdStride)
    contacts.ids(2 * c) = old.ids(2 * last)
    contacts.ids(2 * c + 1) = old.ids(2 * last + 1)

  /** An upper bound of how fast two bodies' points can approach each other at the start of
    * the step: |vA - vB| + |wA| extentA + |wB| extentB. Over the step they close at most this
    * times the time step, so points that far apart are speculative points: a fast ball is
    * caught where it would land instead of sinking deep into a pile within one step (and being
    * pushed out of it at speed).
    */
  private def approachBound(a: Int, b: Int): Double =
    val state = bodies.state
    val sA = a * SoftBodies.Stride
    val sB = b * SoftBodies.Stride
    val dvx = state(sB + VelocityX) - state(sA + VelocityX)
    val dvy = state(sB + VelocityY) - state(sA + VelocityY)
    val bound = math.sqrt(dvx * dvx + dvy * dvy) + math.abs(state(sA + AngularVelocity)) * bodies.bodies(a).extent +
      math.abs(state(sB + AngularVelocity)) * bodies.bodies(b).extent
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
  private def addManifold(table: ContactTable, a: Shape, b: Shape, key: Long, last: Int): Unit =
    val contacts = table.current
    val c = start(contacts, a, b, key, manifold.normalX, manifold.normalY, manifold.pointCount, stiffnessOf(table, last))
    contacts.side(c) = manifold.polygonSide
    cachePlacements(contacts, c)
    val hot = contacts.hot
    val cold = contacts.cold
    var p = 0
    while p < manifold.pointCount do
      setPoint(contacts, c, p, manifold.x(p), manifold.y(p), manifold.separation(p))
      val q = contacts.hotPoint(c, p)
      val r = contacts.coldPoint(c, p)
      cold(r + CachedAnchorAX) = hot(q + AnchorAX); cold(r + CachedAnchorAY) = hot(q + AnchorAY)
      cold(r + CachedAnchorBX) = hot(q + AnchorBX); cold(r + CachedAnchorBY) = hot(q + AnchorBY)
      cold(r + CachedSeparation) = manifold.separation(p)
      contacts.ids(2 * c + p) = manifold.id(p)
      if last >= 0 then
        val old = table.committed
        var o = 0
        while o < old.pointCount(last) do
          if old.ids(2 * last + o) == manifold.id(p) then
            val from = old.hotPoint(last, o)
            hot(q + NormalImpulse) = old.hot(from + NormalImpulse)
            hot(q + TangentImpulse) = old.hot(from + TangentImpulse)
          o += 1
      p += 1

  /** Turns contact c of two circles on their bodies' centres to the normal they meet along:
    * the line of their centres when, moving as at the start of the step, they first touch,
    * or when they come closest within the step if they pass each other (the start's when they
    * touch already). Its arms then lie along that normal, from each centre to the outline, and its
    * separation is the gap along it.
    *
    * Why: the contact keeps its normal for the whole step, and a contact found before the balls
    * touch (speculative, up to a step ahead) has the line of centres of the start, which for two
    * balls glancing past each other is far from the line at impact: the impulses then push
    * along a line that misses the centres at impact (a couple that changes the angular
    * momentum, and a rebound in the wrong direction), and the gap along the start's normal
    * closes before the balls touch. Along the line at impact the collision is as between real
    * balls; along the line of closest approach the gap never closes early.
    */
  private def aimAtImpact(contacts: Contacts, c: Int, circleA: Circle, circleB: Circle): Unit =
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
      cold(r + CachedAnchorAX) = hot(q + AnchorAX); cold(r + CachedAnchorAY) = hot(q + AnchorAY)
      cold(r + CachedAnchorBX) = hot(q + AnchorBX); cold(r + CachedAnchorBY) = hot(q + AnchorBY)
      cold(r + PointX) = bodies.startX(a) + hot(q + AnchorAX)
      cold(r + PointY) = bodies.startY(a) + hot(q + AnchorAY)
      val separation = dx * nx + dy * ny - reach
      cold(r + Separation) = separation
      cold(r + CachedSeparation) = separation

  /** Whether the last step's contact `last` may be kept instead of computing the manifold
    * again: neither body turned by more than `KeepAngle` since it was computed, and the bodies'
    * relative placement changed by less than `persistence` (a shift of B in A's frame plus
    * the largest extent times the change of their relative rotation).
    */
  private def keeps(old: Contacts, last: Int, shapeA: Shape, shapeB: Shape, persistence: Double): Boolean =
    val a = shapeA.body.index
    val b = shapeB.body.index
    val k = last * ColdStride
    val turnA = bodies.startAngle(a) - old.cold(k + CachedAngleA)
    val turnB = bodies.startAngle(b) - old.cold(k + CachedAngleB)
    if math.abs(turnA) >= ContactFinder.KeepAngle || math.abs(turnB) >= ContactFinder.KeepAngle then false
    else
      // B's centre in A's frame now against then, measured in A's frame then:
      // R(-turnA) (cB - cA) - (cB - cA) then.
      val dx = bodies.startX(b) - bodies.startX(a)
      val dy = bodies.startY(b) - bodies.startY(a)
      val c = ContactFinder.cosine(turnA)
      val s = ContactFinder.sine(turnA)
      val relativeX = c * dx + s * dy - old.cold(k + CachedRelativeX)
      val relativeY = -s * dx + c * dy - old.cold(k + CachedRelativeY)
      val extentA = if bodies.bodies(a).fixed then 0.0 else bodies.bodies(a).extent
      val extentB = if bodies.bodies(b).fixed then 0.0 else bodies.bodies(b).extent
      val shift = math.sqrt(relativeX * relativeX + relativeY * relativeY)
      shift + math.max(extentA, extentB) * math.abs(ContactFinder.sine(turnB - turnA)) < persistence

  /** Appends the last step's contact `last` again: the same normal, ids and impulses, its
    * separations updated from the bodies' motion.
    */
  private def keep(table: ContactTable, last: Int, a: Shape, b: Shape, key: Long): Unit =
    val old = table.committed
    val contacts = table.current
    val points = old.pointCount(last)
    val k = old.offset(last)
    val c = start(contacts, a, b, key, old.hot(k + NormalX), old.hot(k + NormalY), points, old.hot(k + Stiffness))
    contacts.side(c) = old.side(last)
    val hot = contacts.hot
    val cold = contacts.cold
    val oldCold = last * ColdStride
    ShortCopy.doubles(old.cold, oldCold, cold, c * ColdStride, ColdStride)
    val ia = contacts.bodyA(c)
    val ib = contacts.bodyB(c)
    val turnA = bodies.startAngle(ia) - old.cold(oldCold + CachedAngleA)
    val turnB = bodies.startAngle(ib) - old.cold(oldCold + CachedAngleB)
    val cA = ContactFinder.cosine(turnA); val sA = ContactFinder.sine(turnA)
    val cB = ContactFinder.cosine(turnB); val sB = ContactFinder.sine(turnB)
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
    val k = c * ColdStride
    contacts.cold(k + CachedAngleA) = bodies.startAngle(a)
    contacts.cold(k + CachedAngleB) = bodies.startAngle(b)
    // cB - cA in the world frame; `keeps` turns the current one back by A's turn since.
    contacts.cold(k + CachedRelativeX) = bodies.startX(b) - bodies.startX(a)
    contacts.cold(k + CachedRelativeY) = bodies.startY(b) - bodies.startY(a)

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
      val c = start(contacts, collision.shape1, collision.shape2, key, nx, ny, count, stiffnessOf(table, last))
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
            if dx * dx + dy * dy <= ContactFinder.UserMatchDistance * ContactFinder.UserMatchDistance then
              val from = old.hotPoint(last, o)
              val q = contacts.hotPoint(c, p)
              contacts.hot(q + NormalImpulse) = old.hot(from + NormalImpulse)
              contacts.hot(q + TangentImpulse) = old.hot(from + TangentImpulse)
            o += 1
        p += 1

  /** Starts contact of shapes (a, b) with normal (nx, ny) from a to b and `points` points: its
    * bodies, key and the pair's friction and restitution (products of the shapes', as in the
    * classic step).
    */
  private def start(contacts: Contacts, a: Shape, b: Shape, key: Long, nx: Double, ny: Double, points: Int,
      stiffness: Double): Int =
    val c = contacts.add(points)
    contacts.shapeA(c) = a
    contacts.shapeB(c) = b
    contacts.bodyA(c) = a.body.index
    contacts.bodyB(c) = b.body.index
    contacts.keys(c) = key
    val k = contacts.offset(c)
    contacts.hot(k + NormalX) = nx
    contacts.hot(k + NormalY) = ny
    contacts.hot(k + Friction) = a.friction * b.friction
    val restitution = a.restitution * b.restitution
    contacts.hot(k + Restitution) = restitution
    if restitution != 0 then contacts.bouncing = true
    contacts.hot(k + Stiffness) = stiffness
    c

  /** The stiffness the last step's contact `last` of the pair had (0 if none: see [[ContactStiffness]]). */
  private def stiffnessOf(table: ContactTable, last: Int): Double =
    if last >= 0 then table.committed.hot(table.committed.offset(last) + Stiffness) else 0.0

private object ContactFinder:
  /** A user kind's point takes over the impulses of a last-step point this close, m. */
  val UserMatchDistance: Double = 0.01

  /** A contact is computed again once either body turned this far since, rad (cos = 0.98). */
  val KeepAngle: Double = PortableMath.acos(0.98)

  /** sin(a) for |a| < KeepAngle, to 1e-9, without the library call (Taylor to a^5). */
  inline def sine(a: Double): Double =
    val a2 = a * a
    a * (1 - a2 / 6 * (1 - a2 / 20))

  /** cos(a) for |a| < KeepAngle, to 1e-10 (Taylor to a^6). */
  inline def cosine(a: Double): Double =
    val a2 = a * a
    1 - a2 / 2 * (1 - a2 / 12 * (1 - a2 / 30))
