package sims.solver

import sims.collision.Collision
import sims.dynamics.Body

/** The classic step's contact solver: the velocity iterations of phase 4 over one step's
  * contact points, kept in flat arrays.
  *
  * Positions do not change during phase 4, so everything a point's correction needs apart from
  * the velocities (the bodies, the arms r1 and r2, the effective masses along n and t, n, 1 + e
  * and mu) is computed once per step by `load` and read from one array by each iteration,
  * instead of being recomputed from the collision objects ten times. The corrections are
  * `Collision.correctVelocity`'s, and they run in wave order (see [[WaveOrder]]): every body
  * sees its points in list order, so the results are the same to the bit as correcting each
  * collision in turn. A collision of a user kind is corrected by its own `correctVelocity`,
  * in its turn: steps with one keep the list order throughout.
  */
private[sims] final class ContactSolver:
  import ContactSolver.*

  private var count = 0
  private var body1 = new Array[Body](64)
  private var body2 = new Array[Body](64)
  /** Non-null at an entry that is a whole collision of a user kind, corrected by itself. */
  private var own = new Array[Collision](64)
  private var data = new Array[Double](64 * Stride)
  // Per point: the wave-order keys of its two bodies (-1 for a fixed body).
  private var keys = new Array[Int](64 * 2)
  // True when a body of the loaded points cannot be ordered in waves (see `orderable`).
  private var unorderable = false

  /** Whether the last classic step detected collisions (its contacts are the detector's). */
  var detected: Boolean = false

  /** Number of entries: contact points of the built-in kinds plus user-kind collisions. */
  def size: Int = count

  /** Number of waves of the last step's order (see [[WaveOrder]]), 0 if it kept list order. */
  def waveCount: Int = waves.waves

  /** Takes the contact points of `collisions` for this step's velocity iterations. */
  def load(collisions: collection.IndexedSeq[Collision]): Unit =
    count = 0
    unorderable = false
    var owned = false
    var c = 0
    while c < collisions.length do
      val collision = collisions(c)
      if collision.solvedInPlace then addPoints(collision)
      else
        ensureRoom()
        own(count) = collision
        body1(count) = null
        body2(count) = null
        count += 1
        owned = true
      c += 1
    // A user kind's correction may touch anything: such steps keep the list order, as do the
    // rare steps with a body the wave order cannot take (see `orderable`).
    if owned || unorderable then waves.clear() else schedule()

  /** Forgets the contacts (a step without collision detection). */
  def clear(): Unit =
    count = 0
    waves.clear()

  private val waves = WaveOrder()
  private var sorted1 = new Array[Body](64)
  private var sorted2 = new Array[Body](64)
  private var sortedData = new Array[Double](64 * Stride)

  /** Puts the points in wave order (see [[WaveOrder]]): the same bits, faster. */
  private def schedule(): Unit =
    waves.clear()
    var e = 0
    while e < count do
      waves.add(keys(e * 2), keys(e * 2 + 1))
      e += 1
    waves.plan()
    if sorted1.length < body1.length then
      sorted1 = new Array[Body](body1.length)
      sorted2 = new Array[Body](body1.length)
      sortedData = new Array[Double](body1.length * Stride)
    var k = 0
    while k < count do
      val from = waves(k)
      sorted1(k) = body1(from)
      sorted2(k) = body2(from)
      ShortCopy.doubles(data, from * Stride, sortedData, k * Stride, Stride)
      k += 1
    val b1 = body1; body1 = sorted1; sorted1 = b1
    val b2 = body2; body2 = sorted2; sorted2 = b2
    val d = data; data = sortedData; sortedData = d

  private def addPoints(c: Collision): Unit =
    c.load()
    val b1 = c.shape1.body
    val b2 = c.shape2.body
    val nx = c.normalX
    val ny = c.normalY
    val key1 = if b1.fixed then -1 else b1.index
    val key2 = if b2.fixed then -1 else b2.index
    if !orderable(b1, key1) || !orderable(b2, key2) then unorderable = true
    val restitutionFactor = 1 + c.shape1.restitution * c.shape2.restitution
    val mu = c.shape1.friction * c.shape2.friction
    var i = 0
    while i < c.pointCount do
      ensureRoom()
      val r1x = c.pointXs(i) - b1.x; val r1y = c.pointYs(i) - b1.y
      val r2x = c.pointXs(i) - b2.x; val r2y = c.pointYs(i) - b2.y
      val k = count * Stride
      data(k) = r1x; data(k + 1) = r1y; data(k + 2) = r2x; data(k + 3) = r2y
      data(k + 4) = nx; data(k + 5) = ny
      data(k + 6) = restitutionFactor; data(k + 7) = mu
      data(k + 8) = Collision.effectiveMass(b1, b2, r1x, r1y, r2x, r2y, nx, ny)
      data(k + 9) = Collision.effectiveMass(b1, b2, r1x, r1y, r2x, r2y, -ny, nx)
      keys(2 * count) = key1
      keys(2 * count + 1) = key2
      body1(count) = b1
      body2(count) = b2
      own(count) = null
      count += 1
      i += 1

  /** False for a moving body without a key (outside the world: not in a world's own step), and
    * for a fixed body with a velocity of -0.0, which an impulse of +0.0 would turn into +0.0
    * at a point of the list order that the wave order does not keep.
    */
  private def orderable(b: Body, key: Int): Boolean =
    if b.fixed then !(negativeZero(b.vx) || negativeZero(b.vy) || negativeZero(b.w))
    else key >= 0

  private def ensureRoom(): Unit =
    if count == body1.length then
      val capacity = 2 * count
      body1 = java.util.Arrays.copyOf(body1, capacity)
      body2 = java.util.Arrays.copyOf(body2, capacity)
      own = java.util.Arrays.copyOf(own, capacity)
      data = java.util.Arrays.copyOf(data, capacity * Stride)
      keys = java.util.Arrays.copyOf(keys, capacity * 2)

  /** One velocity iteration over all contacts (in wave order unless a user kind is loaded). */
  def correctVelocities(h: Double): Unit =
    val d = data
    var e = 0
    while e < count do
      val b1 = body1(e)
      if b1 == null then own(e).correctVelocity(h)
      else
        val k = e * Stride
        Collision.correctVelocityAt(b1, body2(e), d(k), d(k + 1), d(k + 2), d(k + 3), d(k + 4), d(k + 5),
          d(k + 6), d(k + 7), d(k + 8), d(k + 9))
      e += 1

private[sims] object ContactSolver:
  /** Doubles per point: r1x, r1y, r2x, r2y, nx, ny, 1 + e, mu, m, mT. */
  private val Stride = 10

  private inline def negativeZero(d: Double): Boolean =
    java.lang.Double.doubleToRawLongBits(d) == java.lang.Long.MIN_VALUE
