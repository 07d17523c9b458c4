package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Circle, Shape}

/** PairTable against a map: any mix of inserts, removes and stamps, through growth and the
  * clearing out of removed slots, finds exactly the pairs a map holds.
  */
class PairTableSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  private val shapes = IndexedSeq.fill(8)(Circle(1, 1))

  test("property: inserts, removes and stamps leave the table holding what a map holds") {
    val operations = Gen.listOfN(3000, Gen.zip(Gen.choose(0, 2), Gen.choose(0L, 600L), Gen.choose(0, 7)))
    forAll(operations, minSuccessful(30)) { ops =>
      val table = PairTable()
      val model = collection.mutable.Map.empty[Long, (Shape, Long)]
      for ((kind, key, s), step) <- ops.zipWithIndex do
        val slot = table.find(key)
        (slot >= 0) shouldBe model.contains(key)
        kind match
          case 0 => if slot < 0 then { table.insert(key, shapes(s), shapes(7 - s), step); model(key) = (shapes(s), step) }
          case 1 => if slot >= 0 then { table.remove(slot); model.remove(key) }
          case _ => if slot >= 0 then { table.stamp(slot, step); model(key) = (model(key)._1, step) }
      table.size shouldBe model.size
      val seen = (0 until table.slots).filter(table.keyAt(_) >= 0)
        .map(s => table.keyAt(s) -> (table.firstAt(s), table.stampAt(s))).toMap
      seen shouldBe model.toMap
      for (key, (first, _)) <- model do table.secondAt(table.find(key)) shouldBe (shapes(7 - shapes.indexOf(first)))
      table.clear()
      table.size shouldBe 0
      (0 until table.slots).count(table.keyAt(_) != -1) shouldBe 0
      model.keys.foreach(key => table.find(key) shouldBe -1)
    }
  }

  test("clear empties every slot, whether it empties the filled ones alone or all of them") {
    val table = PairTable()
    // Fills, removes and fills again the same few slots more often than the log holds.
    for round <- 0 until 100; key <- 0L until 10L do
      table.insert(key, shapes(0), shapes(1), round)
      table.remove(table.find(key))
    (0L until 10L).foreach(key => table.insert(key, shapes(0), shapes(1), 0))
    table.clear()
    (0 until table.slots).count(table.keyAt(_) != -1) shouldBe 0
    (0 until table.slots).count(table.firstAt(_) != null) shouldBe 0
    // Rebuilt every round: each clear finds its pairs gone.
    for round <- 0 until 50 do
      table.clear()
      (0L until 200L).foreach(key => table.insert(key * 7919 + round, shapes(0), shapes(1), key))
      table.size shouldBe 200
      (0L until 200L).foreach(key => table.stampAt(table.find(key * 7919 + round)) shouldBe key)
      if round > 0 then table.find(199L * 7919 + round - 1) shouldBe -1
  }
