package sims.solver

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks

/** The wave order must keep every body's corrections in list order, and may only move a
  * correction before an earlier one that shares no moving body with it.
  */
class WaveOrderSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private def planned(pairs: Seq[(Int, Int)]): (WaveOrder, Seq[Int]) =
    val order = WaveOrder()
    pairs.foreach((a, b) => order.add(a, b))
    order.plan()
    (order, pairs.indices.map(order(_)))

  test("corrections without a common moving body share a wave; fixed bodies (-1) order nothing") {
    // waves: (0,1) 1, (1,2) 2, (3,4) 1, (-1,0) 2, (2,-1) 3, (-1,-1) 1
    val (order, sequence) = planned(Seq((0, 1), (1, 2), (3, 4), (-1, 0), (2, -1), (-1, -1)))
    order.waves shouldBe 3
    sequence shouldBe Seq(0, 2, 5, 1, 3, 4)
  }

  test("a chain through one body keeps list order, one wave per correction") {
    val (order, sequence) = planned(Seq((5, 1), (5, 2), (3, 5), (5, 4)))
    order.waves shouldBe 4
    sequence shouldBe Seq(0, 1, 2, 3)
  }

  test("clear starts a new list, and keys far apart are taken") {
    val order = WaveOrder()
    order.add(7, 1)
    order.add(7, 2)
    order.clear() // without a plan: the bodies' last waves must be forgotten all the same
    order.size shouldBe 0
    order.add(100000, 7)
    order.add(7, 3)
    order.add(2, 100000)
    order.plan()
    order.waves shouldBe 2 // body 7 starts again from wave 1
    Seq(order(0), order(1), order(2)) shouldBe Seq(0, 1, 2)
  }

  test("property: a permutation that keeps each body's order, with no shared body within a wave") {
    val key = Gen.frequency(1 -> Gen.const(-1), 6 -> Gen.choose(0, 30))
    val pairs = Gen.choose(0, 200).flatMap(n => Gen.listOfN(n, Gen.zip(key, key).suchThat((a, b) => a != b || a < 0)))
    forAll(pairs, minSuccessful(200)) { list =>
      val (order, sequence) = planned(list)
      sequence.sorted shouldBe list.indices
      // Each moving body's corrections come in list order.
      for body <- 0 to 30 do
        val touching = sequence.filter(i => list(i)._1 == body || list(i)._2 == body)
        touching shouldBe touching.sorted
      // The corrections of one wave are consecutive in list order within it and share no body:
      // recompute the waves from the definition and compare.
      val last = scala.collection.mutable.Map.empty[Int, Int].withDefaultValue(0)
      val waves = list.map { (a, b) =>
        val w = math.max(if a < 0 then 0 else last(a), if b < 0 then 0 else last(b)) + 1
        if a >= 0 then last(a) = w
        if b >= 0 then last(b) = w
        w
      }
      sequence shouldBe list.indices.sortBy(i => (waves(i), i))
      order.waves shouldBe (if list.isEmpty then 0 else waves.max)
    }
  }
