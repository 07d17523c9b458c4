package sims.collision

import scala.collection.mutable
import scala.util.Random
import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Circle, Shape, World}
import sims.geometry.Vector2D

/** PairTracker against a set of open pairs, through the ways touches come: in last step's order
  * (its list finds them), with pairs left out, added, swapped, repeated or shuffled, so many new
  * ones that the table grows in the middle of a step, and steps undone, restored and resting.
  * The shapes lie 2 m apart, so a pair not touched ends (none is kept by the hysteresis).
  */
class PairTrackerSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  private val world = World()
  private val shapes = IndexedSeq.tabulate(60) { i =>
    val ball = Circle(0.1, 1)
    ball.pos = Vector2D(2.0 * (i % 10), 2.0 * (i / 10))
    world += ball.asBody
    ball
  }
  private val pairs = for i <- shapes.indices; j <- shapes.indices if i < j yield (shapes(i), shapes(j))

  private def sortedKeys(t: PairTracker, count: Int, first: Int => Shape, second: Int => Shape) = (0 until count).map(k =>
    (first(k), second(k)))

  test("property: begins, ends and the open pairs are what a set of open pairs gives, however the touches come") {
    var fastSteps, growSteps, undone, restored = 0
    forAll(Gen.choose(0L, Long.MaxValue), minSuccessful(40)) { seed =>
      val random = Random(seed)
      val tracker = PairTracker(ordered = false)
      var open = Set.empty[(Shape, Shape)]
      var order = random.shuffle(pairs).take(40).toVector
      var saved: Option[(PairTracker.Saved, Set[(Shape, Shape)])] = None
      for step <- 1 to 60 do
        // This step's touches: mostly last step's order, changed in one of several ways.
        order = random.nextInt(8) match
          case 0 => random.shuffle(order)
          case 1 => order ++ random.shuffle(pairs).take(400) // many new pairs: the table grows
          case 2 => order.filter(_ => random.nextInt(3) > 0)
          case 3 => order.flatMap(p => if random.nextInt(10) == 0 then Seq(p, p) else Seq(p)) // repeated
          case 4 => order.grouped(2).flatMap(g => if random.nextBoolean() then g.reverse else g).toVector
          case 5 => (order ++ random.shuffle(pairs).take(5)).map(p => (random.nextInt(4), p)).sortBy(_._1).map(_._2)
          case _ => order.filter(_ => random.nextInt(20) > 0) ++ random.shuffle(pairs).take(3)
        val before = open
        tracker.beginStep()
        val resting = random.nextInt(15) == 0
        val touched = if resting then Vector.empty else order
        if resting then tracker.touchAllOpen()
        val begun = mutable.ArrayBuffer.empty[(Shape, Shape)]
        for (a, b) <- touched do
          val (x, y) = if random.nextBoolean() then (a, b) else (b, a) // either order of the shapes
          if tracker.touch(x, y) then begun += ((a, b))
        tracker.finishStep(world)
        val now = if resting then before else touched.toSet
        withClue(s"seed $seed, step $step: ") {
          begun.toSet shouldBe (now -- before)
          begun.size shouldBe begun.distinct.size
          sortedKeys(tracker, tracker.begins, tracker.beginFirstShape, tracker.beginSecondShape).toSet shouldBe (now -- before)
          sortedKeys(tracker, tracker.ends, tracker.endFirstShape, tracker.endSecondShape).toSet shouldBe (before -- now)
          val listed = tracker.openPairs()
          listed.first.zip(listed.second).toSet shouldBe now
          listed.keys.toSeq shouldBe listed.keys.toSeq.sorted
        }
        open = now
        if order.size > 300 then order = order.take(60)
        if touched.size > 200 then growSteps += 1
        if !resting && touched.nonEmpty then fastSteps += 1
        random.nextInt(10) match
          case 0 =>
            tracker.undoStep()
            open = before
            tracker.openPairs().first.zip(tracker.openPairs().second).toSet shouldBe open
            undone += 1
          case 1 => saved = Some((tracker.openPairs(), open))
          case 2 if saved.nonEmpty =>
            tracker.restoreOpen(saved.get._1)
            open = saved.get._2
            restored += 1
          case _ =>
    }
    info(s"$fastSteps steps touched pairs, $growSteps with hundreds of new ones; $undone undone, $restored restored")
  }

  test("touches in the last step's order probe the table for none of their pairs, and only for the few out of place") {
    val tracker = PairTracker(ordered = false)
    def step(touches: Seq[(Shape, Shape)]): Long =
      val before = tracker.probes
      tracker.beginStep()
      touches.foreach((a, b) => tracker.touch(a, b))
      tracker.finishStep(world)
      tracker.probes - before
    val order = Random(7).shuffle(pairs).take(1500)
    step(order) shouldBe 1500 // all new: each probes, and is opened
    step(order) shouldBe 0
    // Neighbours swapped, and pairs left out: found near where they were.
    val swapped = order.grouped(2).flatMap(_.reverse).toVector
    step(swapped.filter(_ => Random(3).nextInt(10) > 0)) shouldBe 0
    // A pair far from its place probes; the rest do not.
    step(swapped.last +: swapped.init) shouldBe 1
  }
