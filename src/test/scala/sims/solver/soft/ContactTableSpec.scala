package sims.solver.soft

import scala.util.Random
import org.scalatest.funsuite.AnyFunSuite

/** The contact table's lookup of the last step's contact of a pair: the same answer whether the
  * pairs come in the last step's order (the guess) or not (the table), a pair listed twice included.
  */
class ContactTableSpec extends AnyFunSuite:
  /** A table whose committed generation holds contacts with these keys, in this order. */
  private def committedWith(keys: Long*): ContactTable = committedListing(repeat = false, keys*)

  /** `committedWith`, its contacts marked as possibly listing a pair twice if `repeat`. */
  private def committedListing(repeat: Boolean, keys: Long*): ContactTable =
    val table = ContactTable()
    table.begin()
    for key <- keys do
      val c = table.current.add(1)
      table.current.keys(c) = key
    table.current.pairsRepeat = repeat
    table.commit()
    table.begin()
    table

  test("lastOf finds each committed contact by its pair's key, in the committed order or any other") {
    val keys = Seq(7L, 3L, 12L, 40L, 5L)
    val inOrder = committedWith(keys*)
    assert(keys.map(inOrder.lastOf) == Seq(0, 1, 2, 3, 4))
    val shuffled = committedWith(keys*)
    assert(Seq(40L, 5L, 7L, 12L, 3L, 40L).map(shuffled.lastOf) == Seq(3, 4, 0, 2, 1, 3))
  }

  test("lastOf gives -1 for a pair with no committed contact, and finds the next one after it") {
    val table = committedWith(7L, 3L, 12L)
    assert(Seq(7L, 99L, 3L, 1L, 12L).map(table.lastOf) == Seq(0, -1, 1, -1, 2))
  }

  test("a pair listed twice finds its last contact, even where the one after the last found is its first") {
    val table = committedListing(repeat = true, 7L, 3L, 12L, 3L)
    assert(table.lastOf(7L) == 0)
    assert(table.lastOf(3L) == 3)
    assert(table.lastOf(12L) == 2)
    assert(table.lastOf(3L) == 3)
  }

  test(
    "property: over thousands of contacts, in their order with some shifted, swapped, left out or new, or shuffled, lastOf gives what a map gives") {
    for seed <- 1 to 30 do
      val random = Random(seed)
      // Pairs of shapes (first, second) as PairKey makes them: up to 5 pairs a first shape, the
      // first shapes' indices up to 4,000 (more than the index has buckets for a few thousand).
      def pair(n: Long): Long = (n / 5) << 32 | (n % 5)
      val keys = random.shuffle((0L until 20000L).toVector).take(500 + random.nextInt(3000)).map(pair)
      val table = committedWith(keys*)
      val where = keys.zipWithIndex.toMap
      val asked = random.nextInt(4) match
        case 0 => random.shuffle(keys ++ Seq.fill(500)((4000L + random.nextInt(1000)) << 32))
        case 1 => keys.grouped(3).flatMap(g => if random.nextBoolean() then g.reverse else g).toVector
        case _ => keys.flatMap(k => if random.nextInt(10) == 0 then Seq(k | 8L) else if random.nextInt(10) == 0 then Nil else Seq(k))
      for key <- asked do assert(table.lastOf(key) == where.getOrElse(key, -1), s"seed $seed, key $key")
  }

  test("property: with some pairs listed twice, lastOf gives each pair's last contact, in any order asked") {
    for seed <- 1 to 30 do
      val random = Random(seed)
      val distinct = random.shuffle((0L until 5000L).toVector).take(200 + random.nextInt(1000)).map(n => (n / 3) << 32 | n % 3)
      val keys = random.shuffle(distinct ++ distinct.filter(_ => random.nextInt(20) == 0))
      val table = committedListing(repeat = true, keys*)
      val last = keys.zipWithIndex.toMap // a later index of a key replaces an earlier one
      val asked = if random.nextBoolean() then keys else random.shuffle(keys)
      for key <- asked do assert(table.lastOf(key) == last(key), s"seed $seed, key $key")
  }

  test("a new step looks from the first committed contact again") {
    val table = committedWith(7L, 3L)
    assert(table.lastOf(3L) == 1)
    table.begin()
    assert(table.lastOf(7L) == 0)
    assert(table.lastOf(3L) == 1)
  }

  /** `committedWith`'s table with a step of contacts `next` built on it, not committed yet. */
  private def building(committed: Seq[Long], next: Seq[Long]): ContactTable =
    val table = committedWith(committed*)
    for key <- next do
      val c = table.current.add(1)
      table.current.keys(c) = key
    table

  test("the step's contacts indexed ahead of the commit are found as when the commit indexes them") {
    val ahead = building(Seq(7L, 3L, 12L), Seq(40L, 3L, 5L, 40L))
    ahead.indexCurrent()
    assert(Seq(7L, 3L, 12L).map(ahead.lastOf) == Seq(0, 1, 2)) // the committed ones until the commit
    ahead.commit()
    ahead.begin()
    val atCommit = building(Seq(7L, 3L, 12L), Seq(40L, 3L, 5L, 40L))
    atCommit.commit()
    atCommit.begin()
    val asked = Seq(3L, 40L, 5L, 7L, 12L, 99L)
    assert(asked.map(ahead.lastOf) == Seq(1, 3, 2, -1, -1, -1))
    assert(asked.map(atCommit.lastOf) == asked.map(ahead.lastOf))
  }

  test("a step that fails after indexing its contacts ahead (no commit) leaves the committed ones found") {
    def failedThenNext(): ContactTable =
      val table = building(Seq(7L, 3L, 12L), Seq(40L, 5L))
      table.indexCurrent()
      table.begin() // the next step, the failed one's contacts dropped
      table.current.keys(table.current.add(1)) = 12L
      table.commit()
      table
    val next = failedThenNext()
    next.begin()
    assert(Seq(12L, 7L, 40L).map(next.lastOf) == Seq(0, -1, -1))
    val undone = failedThenNext()
    undone.uncommit() // that step failed too, after its commit
    undone.begin()
    assert(Seq(7L, 3L, 12L, 40L, 5L).map(undone.lastOf) == Seq(0, 1, 2, -1, -1))
  }

  test("ranges written into shared regions and gathered equal the same contacts added one after another") {
    import ContactTable.*
    val points = Seq(1, 2, 2, 1, 1, 2, 1)
    // Each contact's hot, cold and record slots numbered apart from the others'.
    def fill(contacts: Contacts, c: Int, n: Int): Unit =
      contacts.keys(c) = 100L + n
      contacts.bodyA(c) = n
      for i <- 0 until Header + contacts.pointCount(c) * HotPoint do contacts.hot(contacts.offset(c) + i) = 1000.0 * n + i
      for i <- 0 until ColdStride do contacts.cold(contacts.coldOffset(c) + i) = -1000.0 * n - i
      for i <- 0 until RecordStride do contacts.records(c * RecordStride + i) = 0.5 * n + i
    val serial = Contacts()
    for (p, n) <- points.zipWithIndex do fill(serial, serial.add(p), n)
    // Two ranges of pairs (4 and 3), each with room for a two-point contact per pair; the
    // second range makes one contact fewer than it has pairs, which leaves a gap.
    val gathered = Contacts()
    gathered.reserve(8)
    val ranges = Seq(Contacts(), Contacts())
    ranges(0).share(gathered, 0, 4)
    ranges(1).share(gathered, 4, 8)
    for (p, n) <- points.zipWithIndex do
      val range = ranges(if n < 4 then 0 else 1)
      fill(range, range.add(p), n)
    gathered.extend(7, 8)
    gathered.place(ranges(0), 0)
    gathered.place(ranges(1), 4)
    assert(ranges(1).offset(0) == 4 * MostHot)
    for copy <- Seq(gathered, gathered.copy()) do
      assert(copy.count == 7)
      for c <- 0 until 7 do
        assert(copy.keys(c) == serial.keys(c) && copy.bodyA(c) == serial.bodyA(c))
        assert(copy.pointCount(c) == serial.pointCount(c))
        for p <- 0 until copy.pointCount(c); i <- 0 until HotPoint do
          assert(copy.hot(copy.hotPoint(c, p) + i) == serial.hot(serial.hotPoint(c, p) + i))
        for i <- 0 until ColdStride do assert(copy.cold(copy.coldOffset(c) + i) == serial.cold(serial.coldOffset(c) + i))
        for i <- 0 until RecordStride do assert(copy.records(c * RecordStride + i) == serial.records(c * RecordStride + i))
    // The copy packs the blocks: no gap left.
    assert(gathered.copy().hotSize == serial.hotSize && gathered.copy().coldSize == serial.coldSize)
  }

  test("a range that would outgrow its shared region is refused, naming the region") {
    val gathered = Contacts()
    val range = Contacts()
    gathered.reserve(1)
    range.share(gathered, 0, 1)
    range.add(2) // a two-point contact fills a pair's room
    val error = intercept[IllegalStateException](range.add(1))
    assert(error.getMessage.contains("outgrew its region"))
  }

  test("a detector of the user's that lists a pair twice: the step's contacts say pairs may repeat, and the last is found") {
    import sims.collision.{CircleCollision, Collision, Detector}
    import sims.dynamics.{Circle, World}
    import sims.geometry.Vector2D
    class Twice(val world: World) extends Detector:
      private var found = Vector.empty[Collision]
      def collisions = found
      def detect(): Unit =
        val circles = world.shapes.collect { case c: Circle => c }
        found = Vector(CircleCollision(circles(0), circles(1)), CircleCollision(circles(0), circles(1)))
    val world = World(Twice(_))
    world.gravity = Vector2D.Null
    world.solver = sims.solver.SoftStep()
    val a = Circle(0.1, 1)
    val b = Circle(0.1, 1)
    b.pos = Vector2D(0.15, 0)
    world += a.asBody
    world += b.asBody
    world.step()
    val table = world.workspace(classOf[SoftWorkspace], SoftWorkspace()).table
    assert(table.committed.count == 2 && table.committed.pairsRepeat)
    table.begin()
    assert(table.lastOf(table.committed.keys(0)) == 1)
  }
