package sims.solver.soft

import sims.collision.PairKey
import sims.dynamics.Shape

/** The soft step's contacts: one record per touching (or nearly touching) pair of shapes, with
  * at most two points, in flat arrays (see docs/two-solvers.md).
  *
  * Two generations are kept: the committed one (the last step's contacts, with the impulses
  * they ended with) and the one being built for this step. A new contact finds the last
  * step's record of the same shape pair through an index by the pair (never by position
  * in a list: [[sims.collision.PairKey]]), and each new point takes over the impulses of the old point with the same
  * feature id (warm starting). `commit()` makes the new generation the last step's; a step
  * that fails before it leaves the committed one as it was.
  */
private[sims] final class ContactTable:
  /** The generation being built (this step's contacts). */
  var current: Contacts = Contacts()
  /** The committed generation (the last step's contacts). */
  var committed: Contacts = Contacts()
  // The committed contacts by pair key; and the index of the current ones, when `indexCurrent`
  // made it ahead of `commit` (false again at `begin`: a step that fails before its commit
  // keeps the committed contacts and their index).
  private var byKey = ContactTable.Index()
  private var nextByKey = ContactTable.Index()
  private var nextIndexed = false
  private val lookup = ContactTable.Lookup(this)

  /** Starts building this step's contacts. */
  def begin(): Unit =
    current.clear()
    nextIndexed = false
    lookup.restart()

  /** The committed contact of the shape pair `key`, or -1 (the table's own [[ContactTable.Lookup]]). */
  def lastOf(key: Long): Int = lookup.lastOf(key)

  // The committed contact of the shape pair `key`, or -1, trying committed contact `guess` first.
  private def find(key: Long, guess: Int): Int = byKey.find(committed, key, guess)

  /** Indexes this step's contacts for the next step's lookups now, rather than in `commit`: it
    * reads them only, so that it may run beside other readers of the step's contacts.
    */
  def indexCurrent(): Unit =
    nextByKey.build(current)
    nextIndexed = true

  /** Makes this step's contacts the last step's. */
  def commit(): Unit =
    val built = current
    current = committed
    committed = built
    if nextIndexed then
      val index = byKey
      byKey = nextByKey
      nextByKey = index
      nextIndexed = false
    else byKey.build(committed)
    lookup.restart()

  /** Makes the last step's contacts the committed ones again (a step failed after `commit`). */
  def uncommit(): Unit =
    nextIndexed = false
    commit()

  /** A copy of the committed generation (for a snapshot of the world). */
  def copyCommitted(): Contacts = committed.copy()

  /** Puts back a copy taken by `copyCommitted` as the committed generation (null: none). */
  def restoreCommitted(saved: Contacts): Unit =
    committed = if saved == null then Contacts() else saved.copy()
    nextIndexed = false
    byKey.build(committed)
    lookup.restart()

private[sims] object ContactTable:
  /** One generation's contacts by pair key (`PairKey`): each shape's contacts as the first of
    * their pair, in a chain, and a bit per hash of the keys (a Bloom filter, one hash): a pair
    * whose bit is clear had no contact, which most candidate pairs without one learn there, in a
    * filter small enough to stay in the cache, instead of by a walk of the chain. At least 8
    * bits per contact.
    */
  final class Index:
    // Per bucket of first shapes (a shape's world index, the first half of a pair's key, modulo
    // the buckets: a power of two, at least the contacts), its first indexed contact, or -1; per
    // contact, the next one in its bucket, or -1: the contacts of a bucket in a chain, in contact
    // order. Built in one pass over small arrays (a bucket, a contact's link), in much the order
    // of the shapes, where a hash table's inserts each missed the cache.
    private var head = Array.fill(16)(-1)
    private var next = new Array[Int](0)
    // The buckets the last build set, to reset them (not the whole array).
    private var heads = new Array[Int](0)
    private var headCount = 0
    // Whether a lookup may guess: not when a pair is listed twice, since a lookup finds its
    // last contact, which a guess might miss.
    private var guessing = true
    private var filter = new Array[Long](1)
    private var filterShift = 58 // 64 - log2(the filter's bits)

    /** Indexes the contacts of `contacts`. */
    def build(contacts: Contacts): Unit =
      val count = contacts.count
      if head.length < count || head.length > 8 * count && head.length > 16 then
        head = Array.fill(math.max(16, 2 * Integer.highestOneBit(math.max(count, 1))))(-1)
      else
        var h = 0
        while h < headCount do
          head(heads(h)) = -1
          h += 1
      headCount = 0
      if next.length < count then next = new Array[Int](2 * count)
      // 8 to 64 bits per contact: a count that goes up and down does not reallocate every step.
      val needed = 8L * count
      val bits = 64L * filter.length
      if bits < needed || bits > 8 * needed && bits > 64 then
        filter = new Array[Long](math.max(1, Integer.highestOneBit(count) / 4))
      else java.util.Arrays.fill(filter, 0L)
      filterShift = 64 - Integer.numberOfTrailingZeros(64 * filter.length)
      val keys = contacts.keys
      var twice = false
      // From the last contact back, so that each chain runs in contact order.
      var c = count - 1
      while c >= 0 do
        val key = keys(c)
        val first = bucketOf(key)
        val later = head(first)
        if later < 0 then
          if headCount == heads.length then heads = java.util.Arrays.copyOf(heads, math.max(16, 2 * headCount))
          heads(headCount) = first
          headCount += 1
        else if contacts.pairsRepeat && !twice then
          // A pair listed twice has its other contact in this bucket.
          var e = later
          while e >= 0 && keys(e) != key do e = next(e)
          twice = e >= 0
        next(c) = later
        head(first) = c
        val bit = filterBit(key)
        filter(bit >>> 6) |= 1L << (bit & 63)
        c -= 1
      guessing = !twice

    /** The contact of the pair `key` among `contacts` (the ones indexed), or -1, trying contact
      * `guess` first, then (unless the filter rules the pair out) those near it, then the bucket
      * of the pair's first shape (its last contact, for a pair listed twice).
      */
    def find(contacts: Contacts, key: Long, guess: Int): Int =
      if guessing && guess < contacts.count && contacts.keys(guess) == key then guess
      else if !mayHave(key) then -1 // before the search near the guess, which a pair with no contact would run to its end
      else
        val near = if guessing then PairKey.near(contacts.keys, contacts.count, guess, key) else -1
        if near >= 0 then near
        else
          var found = -1
          var e = head(bucketOf(key))
          while e >= 0 do
            if contacts.keys(e) == key then found = e
            e = next(e)
          found

    // The bucket of a pair's first shape (the key's first half, see PairKey.of).
    private inline def bucketOf(key: Long): Int = (key >>> 32).toInt & (head.length - 1)

    private def mayHave(key: Long): Boolean =
      val bit = filterBit(key)
      (filter(bit >>> 6) & (1L << (bit & 63))) != 0

    private inline def filterBit(key: Long): Int = ((key * 0x9e3779b97f4a7c15L) >>> filterShift).toInt

  /** Finds the committed contacts of pairs for one reader: it first tries the committed contact
    * after the one it found last (the pairs come in much the same order every step, so that is
    * usually the one: a comparison of keys instead of a probe of the index), then the table's
    * filter, which tells most pairs without a contact, then the contacts near that one, then the
    * index. Reads the table only: readers on several threads at once each have their own.
    */
  final class Lookup(val table: ContactTable):
    private var guess = 0

    /** Starts again from the first committed contact (a new step). */
    def restart(): Unit = guess = 0

    /** The committed contact of the shape pair `key`, or -1. */
    def lastOf(key: Long): Int =
      val last = table.find(key, guess)
      if last >= 0 then guess = last + 1
      last

  // A contact's hot block in `Contacts.hot`, at `offset(c)`: what the substeps' passes read and
  // write, `Header` doubles, then `HotPoint` per point. Compact, because the passes sweep it
  // twelve times a step: a ball's contact (one point) is 16 doubles, two cache lines. (With 4
  // more doubles a point, large_pyramid's step took 6.5% longer, ballpit-4000's 2%.)
  inline val NormalX = 0
  inline val NormalY = 1
  inline val Friction = 2
  inline val BiasRate = 3
  inline val MassScale = 4
  inline val ImpulseScale = 5
  inline val Header = 6

  /** A contact's side A is a circle on its body's centre (`Contacts.turnless`), or a fixed body
    * opposite such a circle: a circle's arm lies along the normal (its manifolds put the point
    * on the line from its centre along the normal), so its turn moves no outline along the
    * normal and a push along the normal gives it no spin; a fixed body does not turn.
    */
  inline val TurnlessA = 1
  /** As [[TurnlessA]], for side B. */
  inline val TurnlessB = 2
  /** Both sides turnless: the normal row has no turn at all, and the passes take it a short way. */
  inline val Turnless = 3
  // Offsets in a point's hot block.
  inline val AnchorAX = 0 // arm from A's centre at the start of the step
  inline val AnchorAY = 1
  inline val AnchorBX = 2 // arm from B's centre
  inline val AnchorBY = 3
  inline val BaseSeparation = 4 // separation minus n . (anchorB - anchorA); a turnless contact's: the separation
  inline val NormalMass = 5
  inline val TangentMass = 6
  inline val NormalImpulse = 7 // accumulated (and warm started)
  inline val TangentImpulse = 8
  inline val TotalNormalImpulse = 9 // the normal impulse applied over the step: its substeps and restitution
  inline val HotPoint = 10
  /** The most hot doubles one contact takes: two points. */
  inline val MostHot = Header + 2 * HotPoint

  // A contact's record in `Contacts.records`, at `c * RecordStride`: what the passes need only
  // for bouncing contacts, and what the step's preparation and end read.
  inline val Restitution = 0
  inline val Stiffness = 1 // the angular frequency a loaded contact was stiffened to (0: never)
  inline val Stiffened = 2 // the stiffness whose softness the hot block holds, carried with it (0: the plain softness)
  inline val RecordHeader = 3
  // Offsets in a point's record.
  inline val MaxNormalImpulse = 0 // the largest normal impulse applied in one solve
  inline val RelativeVelocity = 1 // the normal approach: at the start, plus gravity and forces until the point pushed
  inline val ImpactGap = 2 // the separation when the point first pushed this step (0 if it was closed)
  inline val RecordPoint = 3
  inline val RecordStride = RecordHeader + 2 * RecordPoint

  // A contact's hot block and record as the save format writes them, one block: the header, then
  // each point's, in this order, each entry an offset in the hot block or (-1 - x) offset x in
  // the record. (The format's order is the hot block's before the record was split off; format
  // 4 had no ImpactGap.)
  private val SavedHeader = Array(NormalX, NormalY, Friction, -1 - Restitution, BiasRate, MassScale, ImpulseScale,
    -1 - Stiffness)
  private val SavedPoint = Array(AnchorAX, AnchorAY, AnchorBX, AnchorBY, BaseSeparation, NormalMass, TangentMass,
    NormalImpulse, TangentImpulse, -1 - MaxNormalImpulse, -1 - RelativeVelocity, TotalNormalImpulse, -1 - ImpactGap)

  /** Number of doubles a point has in the saved block of format `version`. */
  def savedPoint(version: Int): Int = if version >= 5 then SavedPoint.length else SavedPoint.length - 1

  /** Contact c's hot block and record in the save format's order. */
  def saved(contacts: Contacts, c: Int): Array[Double] =
    val slots = SavedHeader.length + contacts.pointCount(c) * SavedPoint.length
    Array.tabulate(slots) { i =>
      val (inHot, at) = savedSlot(contacts, c, i)
      if inHot then contacts.hot(at) else contacts.records(at)
    }

  /** Sets contact c's hot block and record from `read`, which gives them in the save format's
    * order with `perPoint` doubles a point (see `savedPoint`; a point's later slots are 0).
    */
  def load(contacts: Contacts, c: Int, read: () => Double, perPoint: Int): Unit =
    def put(i: Int, value: Double): Unit =
      val (inHot, at) = savedSlot(contacts, c, i)
      if inHot then contacts.hot(at) = value else contacts.records(at) = value
    for i <- SavedHeader.indices do put(i, read())
    for p <- 0 until contacts.pointCount(c); k <- SavedPoint.indices do
      put(SavedHeader.length + p * SavedPoint.length + k, if k < perPoint then read() else 0.0)

  /** Where slot i of contact c's saved block is: in `hot` or in `records`, and at which index. */
  private def savedSlot(contacts: Contacts, c: Int, i: Int): (Boolean, Int) =
    if i < SavedHeader.length then
      val code = SavedHeader(i)
      if code >= 0 then (true, contacts.offset(c) + code) else (false, c * RecordStride - 1 - code)
    else
      val p = (i - SavedHeader.length) / SavedPoint.length
      val code = SavedPoint((i - SavedHeader.length) % SavedPoint.length)
      if code >= 0 then (true, contacts.hotPoint(c, p) + code) else (false, contacts.recordPoint(c, p) - 1 - code)

  // A contact's cold block in `Contacts.cold`, at `coldOffset(c)`: what the collision stage
  // keeps for the next step. The bodies' placements when the manifold was computed: both
  // rotations and cB - cA, for keeping it (see ContactFinder).
  inline val CachedAngleA = 0
  inline val CachedAngleB = 1
  inline val CachedRelativeX = 2
  inline val CachedRelativeY = 3
  inline val ColdHeader = 4
  // Offsets in a point's cold block.
  inline val Separation = 0 // at the start of the step
  inline val PointX = 1 // world position at the start of the step (A's anchor point)
  inline val PointY = 2
  inline val CachedAnchorAX = 3 // anchors (world frame) and separation when computed
  inline val CachedAnchorAY = 4
  inline val CachedAnchorBX = 5
  inline val CachedAnchorBY = 6
  inline val CachedSeparation = 7
  inline val ColdPoint = 8
  inline val ColdStride = ColdHeader + 2 * ColdPoint

  /** `Contacts.side` of a contact never kept (two circles on their bodies' centres, whose pairs
    * are collided every step): its cold block's placements and anchors for keeping are not
    * written (see `cachedSlot`).
    */
  inline val Uncached = -2

  /** Whether slot k of a cold block holds what keeping a contact compares with: the bodies'
    * placements, or a point's anchors and separation as computed.
    */
  def cachedSlot(k: Int): Boolean = k < ColdHeader || (k - ColdHeader) % ColdPoint >= CachedAnchorAX

/** One generation of contacts, in flat arrays: contact c has shapes, bodies (their indices),
  * the pair's key, point count and ids, the polygon side a polygon-circle contact was measured
  * from, a hot block of doubles at `offset(c)` in `hot`, a record at `c * RecordStride` in
  * `records` and a cold block of `ColdStride` doubles at `coldOffset(c)` in `cold` (see
  * [[ContactTable]]'s offsets).
  *
  * A contact's hot and cold blocks are found through its offsets, so the contacts of a range of
  * pairs collided on another thread may be written straight into a region of this generation's
  * `hot` and `cold` (see `share`): gathering them then copies the per-contact arrays alone.
  */
private[sims] final class Contacts:
  import ContactTable.*

  /** Number of contacts. */
  var count: Int = 0
  /** The contacts the solver's passes take: the first `active` (the rest are carried over
    * unchanged from the last step: pairs asleep).
    */
  var active: Int = 0
  /** Whether a contact with restitution was added since the last `clear`: without one, the
    * passes that only concern bouncing points have nothing to do.
    */
  var bouncing: Boolean = false
  /** Whether a pair may have more than one contact (a detector of the user's may list a pair
    * twice; the built-in one lists each pair once): the index then looks for a pair's last.
    */
  var pairsRepeat: Boolean = false
  /** The substep and damping ratio this generation's stiffened contacts (see
    * [[ContactTable.Stiffened]]) had their softness worked out for; NaN until it is prepared.
    */
  var stiffenedH, stiffenedZeta: Double = Double.NaN
  var shapeA, shapeB: Array[Shape] = new Array[Shape](16)
  var bodyA, bodyB: Array[Int] = new Array[Int](16)
  var keys: Array[Long] = new Array[Long](16)
  var pointCount: Array[Int] = new Array[Int](16)
  var ids: Array[Int] = new Array[Int](32)
  var side: Array[Int] = new Array[Int](16)
  /** Per contact, whether both its shapes' contact events were on when it was made. */
  var reportsEvents: Array[Boolean] = new Array[Boolean](16)
  /** Per contact, which of its sides turn none of its points along its normal
    * ([[ContactTable.TurnlessA]], [[ContactTable.TurnlessB]]; see [[ContactConstraints]]).
    */
  var turnless: Array[Byte] = new Array[Byte](16)
  var offset: Array[Int] = new Array[Int](16)
  var coldOffset: Array[Int] = new Array[Int](16)
  var hot: Array[Double] = new Array[Double](16 * (Header + HotPoint))
  /** Doubles of `hot` in use (the blocks end there; a shared generation's may leave gaps). */
  var hotSize: Int = 0
  var cold: Array[Double] = new Array[Double](16 * ColdStride)
  /** Doubles of `cold` in use. */
  var coldSize: Int = 0
  // Where the region of `hot` and `cold` this generation writes into ends, when `share` gave it one.
  private var hotLimit, coldLimit = Int.MaxValue
  /** Per contact c, its record at `c * RecordStride` (see [[ContactTable]]'s offsets). */
  var records: Array[Double] = new Array[Double](16 * RecordStride)
  /** Appends an empty contact of `points` points and returns its index. */
  def add(points: Int): Int =
    if count == keys.length then grow(2 * count)
    val size = Header + points * HotPoint
    if hotSize + size > hotLimit || coldSize + ColdStride > coldLimit then
      throw IllegalStateException(s"a shared range of contacts outgrew its region: hot $hotSize + $size of $hotLimit, " +
        s"cold $coldSize + $ColdStride of $coldLimit")
    if hotSize + size > hot.length then hot = java.util.Arrays.copyOf(hot, 2 * (hotSize + size))
    if coldSize + ColdStride > cold.length then cold = java.util.Arrays.copyOf(cold, 2 * (coldSize + ColdStride))
    offset(count) = hotSize
    coldOffset(count) = coldSize
    pointCount(count) = points
    hotSize += size
    coldSize += ColdStride
    count += 1
    count - 1

  // Pairs p of a shared stage have their room for a contact (two points at most) at
  // `hotSize + p * MostHot` and `coldSize + p * ColdStride`, after the blocks in use.
  private inline def hotRoom(pair: Int): Int = hotSize + pair * MostHot
  private inline def coldRoom(pair: Int): Int = coldSize + pair * ColdStride

  /** Makes room for a contact of each of `pairs` pairs after the blocks in use, keeping them:
    * the regions `share` hands out.
    */
  def reserve(pairs: Int): Unit =
    if hotRoom(pairs) > hot.length then hot = java.util.Arrays.copyOf(hot, 2 * hotRoom(pairs))
    if coldRoom(pairs) > cold.length then cold = java.util.Arrays.copyOf(cold, 2 * coldRoom(pairs))

  /** Empties this generation and makes it write its contacts' hot and cold blocks into `into`'s
    * arrays, in the room of pairs `firstPair` until `endPair` (made by `into.reserve`), never past
    * it: a range of pairs collided on its own thread, its blocks where the step's passes will read
    * them. Gathered with `into.place`.
    */
  def share(into: Contacts, firstPair: Int, endPair: Int): Unit =
    clear()
    hot = into.hot
    cold = into.cold
    hotSize = into.hotRoom(firstPair)
    coldSize = into.coldRoom(firstPair)
    hotLimit = into.hotRoom(endPair)
    coldLimit = into.coldRoom(endPair)

  /** Counts `more` contacts as added after the present ones, their slots to be filled by `place`,
    * and the room of `pairs` pairs (see `reserve`) as in use.
    */
  def extend(more: Int, pairs: Int): Unit =
    if count + more > keys.length then grow(2 * (count + more))
    count += more
    hotSize = hotRoom(pairs)
    coldSize = coldRoom(pairs)

  /** Copies every contact of `from` (but its `bouncing`) to contacts `base` on: room made by
    * `extend`, their hot and cold blocks already in this generation's arrays (see `share`). Writes
    * only those contacts' slots, so that several generations may be gathered into one at once.
    */
  def place(from: Contacts, base: Int): Unit =
    val n = from.count
    System.arraycopy(from.shapeA, 0, shapeA, base, n); System.arraycopy(from.shapeB, 0, shapeB, base, n)
    System.arraycopy(from.bodyA, 0, bodyA, base, n); System.arraycopy(from.bodyB, 0, bodyB, base, n)
    System.arraycopy(from.keys, 0, keys, base, n); System.arraycopy(from.pointCount, 0, pointCount, base, n)
    System.arraycopy(from.ids, 0, ids, 2 * base, 2 * n); System.arraycopy(from.side, 0, side, base, n)
    System.arraycopy(from.reportsEvents, 0, reportsEvents, base, n)
    System.arraycopy(from.turnless, 0, turnless, base, n)
    System.arraycopy(from.offset, 0, offset, base, n); System.arraycopy(from.coldOffset, 0, coldOffset, base, n)
    System.arraycopy(from.records, 0, records, base * RecordStride, n * RecordStride)

  /** Forgets every contact. */
  def clear(): Unit =
    count = 0
    active = 0
    bouncing = false
    pairsRepeat = false
    stiffenedH = Double.NaN
    stiffenedZeta = Double.NaN
    hotSize = 0
    coldSize = 0
    hotLimit = Int.MaxValue
    coldLimit = Int.MaxValue

  /** Where point p of contact c starts in `hot`. */
  inline def hotPoint(c: Int, p: Int): Int = offset(c) + Header + p * HotPoint

  /** Where point p of contact c's record starts in `records`. */
  inline def recordPoint(c: Int, p: Int): Int = c * RecordStride + RecordHeader + p * RecordPoint

  /** Where point p of contact c starts in `cold`. */
  inline def coldPoint(c: Int, p: Int): Int = coldOffset(c) + ColdHeader + p * ColdPoint

  /** A deep copy, its blocks packed one after another (a shared generation's gaps left out). */
  def copy(): Contacts =
    val c = Contacts()
    c.grow(math.max(count, 16))
    c.active = active
    c.bouncing = bouncing
    c.pairsRepeat = pairsRepeat
    System.arraycopy(shapeA, 0, c.shapeA, 0, count); System.arraycopy(shapeB, 0, c.shapeB, 0, count)
    System.arraycopy(bodyA, 0, c.bodyA, 0, count); System.arraycopy(bodyB, 0, c.bodyB, 0, count)
    System.arraycopy(keys, 0, c.keys, 0, count); System.arraycopy(ids, 0, c.ids, 0, 2 * count)
    System.arraycopy(side, 0, c.side, 0, count); System.arraycopy(reportsEvents, 0, c.reportsEvents, 0, count)
    System.arraycopy(turnless, 0, c.turnless, 0, count)
    System.arraycopy(records, 0, c.records, 0, count * RecordStride)
    var n = 0
    while n < count do
      val copied = c.add(pointCount(n))
      System.arraycopy(hot, offset(n), c.hot, c.offset(copied), Header + pointCount(n) * HotPoint)
      System.arraycopy(cold, coldOffset(n), c.cold, c.coldOffset(copied), ColdStride)
      n += 1
    c

  private def grow(capacity: Int): Unit =
    shapeA = java.util.Arrays.copyOf(shapeA, capacity); shapeB = java.util.Arrays.copyOf(shapeB, capacity)
    bodyA = java.util.Arrays.copyOf(bodyA, capacity); bodyB = java.util.Arrays.copyOf(bodyB, capacity)
    keys = java.util.Arrays.copyOf(keys, capacity); pointCount = java.util.Arrays.copyOf(pointCount, capacity)
    ids = java.util.Arrays.copyOf(ids, 2 * capacity); side = java.util.Arrays.copyOf(side, capacity)
    reportsEvents = java.util.Arrays.copyOf(reportsEvents, capacity)
    turnless = java.util.Arrays.copyOf(turnless, capacity)
    offset = java.util.Arrays.copyOf(offset, capacity)
    coldOffset = java.util.Arrays.copyOf(coldOffset, capacity)
    records = java.util.Arrays.copyOf(records, capacity * RecordStride)
