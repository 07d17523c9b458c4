package sims.solver

import java.lang.management.ManagementFactory
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import scala.jdk.CollectionConverters.*
import sims.collision.GridDetector
import sims.dynamics.{Circle, World}
import sims.geometry.Vector2D
import sims.solver.SoftStepSpec.{Plate, PlateCollision}
import sims.scenes.{BenchScenes, StateFingerprint}

/** The soft step's workers: the same bits for any number of them, no thread for one, nothing
  * allocated per step by a pool. (JVM only: it counts the JVM's threads and their allocation.)
  */
class SoftStepWorkersSpec extends AnyFunSuite with Matchers:
  private val threads = ManagementFactory.getThreadMXBean.asInstanceOf[com.sun.management.ThreadMXBean]

  /** The scene stepped `steps` times under `SoftStep(workers = workers)`, sleeping off. */
  private def stepped(name: String, steps: Int, workers: Int): World =
    val world = BenchScenes.find(name).get.build().world
    world.enableSleep = false
    world.solver = SoftStep(workers = workers)
    for _ <- 1 to steps do world.step()
    world

  private def workerThreads: Seq[Thread] =
    Thread.getAllStackTraces.keySet.asScala.toSeq.filter(_.getName.startsWith("sims-worker-"))

  // Big enough that the contacts are cut into blocks and the bodies shared out in ranges (ball
  // pit, pyramid, wall), with joints (the grid) and ragdolls that land (rain).
  for (name, steps) <- Seq("ballpit-8000" -> 40, "large_pyramid-70" -> 40, "smash-60x40" -> 30,
      "joint_grid-70" -> 20, "rain-1x12x5" -> 60) do
    test(s"$name after $steps steps: the same bits under 1, 2, 3 and 4 workers") {
      val fingerprints = (1 to 4).map(w => StateFingerprint(stepped(name, steps, w)))
      fingerprints.distinct shouldBe fingerprints.take(1)
    }

  test("many_pyramids-2x10's contact events, step by step: the same under 1 and 2 workers (the open pairs judged in ranges)") {
    // Over 2,048 open pairs (boxes on boxes, and side by side), so that two workers judge those
    // not touched in ranges; pairs end as shapes stop colliding and as boxes fly off.
    def events(workers: Int): Seq[(Seq[(Int, Int)], Seq[(Int, Int)], Int)] =
      val world = BenchScenes.find("many_pyramids-2x10").get.build().world
      world.enableSleep = false
      world.solver = SoftStep(workers = workers)
      val boxes = world.bodies.filterNot(_.fixed)
      for step <- 1 to 60 yield
        if step == 20 then boxes.take(40).foreach(_.shapes.foreach(_.collidable = false))
        if step == 30 then boxes.slice(500, 520).foreach(_.linearVelocity = Vector2D(0, 4))
        world.step()
        val log = world.contactEvents
        (log.begins.map(b => (b.shape1.worldIndex, b.shape2.worldIndex)).toSeq,
          log.ends.map(e => (e.shape1.worldIndex, e.shape2.worldIndex)).toSeq, log.touching.size)
    val one = events(1)
    events(2) shouldBe one
    one.map(_._3).min should be > 2048
    one.drop(20).map(_._2.size).sum should be > 100 // pairs ended
  }

  test("a world with one worker starts no thread; two workers, one thread for every such world") {
    // Threads by identity: another class loader's copy of the library (another project's tests
    // in this JVM) has pools of its own, with the same names.
    val before = workerThreads.toSet
    stepped("ballpit-8000", 5, 1)
    workerThreads.toSet shouldBe before
    stepped("ballpit-8000", 5, 2)
    stepped("ballpit-8000", 5, 2)
    val started = workerThreads.toSet -- before
    started.size should be <= 1
    started.map(_.getName).subsetOf(Set("sims-worker-1-of-2")) shouldBe true
  }

  test("a step with two workers allocates under 1 KB, the pool's thread included") {
    // 1,000 steps: the JIT's compiled step, and the pile past the growth of its contact arrays.
    val world = stepped("ballpit-4000", 1000, 2)
    val ids = (Thread.currentThread +: workerThreads).map(_.getId)
    def allocated = ids.map(threads.getThreadAllocatedBytes).sum
    val before = allocated
    for _ <- 1 to 200 do world.step()
    (allocated - before) / 200.0 should be < 1024.0
  }

  test("a pile with a pair of the user's kinds: the same bits under 1 and 2 workers, the user's methods on the stepping thread") {
    val callers = java.util.concurrent.ConcurrentHashMap.newKeySet[Thread]()
    def pile(workers: Int): World =
      val world = BenchScenes.find("ballpit-4000").get.build().world
      world.enableSleep = false
      world.solver = SoftStep(workers = workers)
      val detector = world.detector.asInstanceOf[GridDetector]
      detector.detectionMethods += { case (c: Circle, p: Plate) =>
        callers.add(Thread.currentThread)
        c.pos.y - c.radius <= p.level && math.abs(c.pos.x) <= 1
      }
      detector.collisionMethods += { case (c: Circle, p: Plate) => PlateCollision(p, c) }
      // Among the balls of the pile (as it starts), so that pairs with the plate come and go.
      val balls = world.shapes.collect { case c: Circle => c.pos.y }
      val plate = Plate(balls.sum / balls.size, halfWidth = 1).asBody
      plate.fixed = true
      world += plate
      for _ <- 1 to 30 do world.step()
      world
    val one = StateFingerprint(pile(1))
    callers.asScala.toSet shouldBe Set(Thread.currentThread)
    StateFingerprint(pile(2)) shouldBe one
    callers.asScala.toSet shouldBe Set(Thread.currentThread)
  }

  test("methods the user changes between steps are used from the next step on, under 2 workers as under 1") {
    def changed(workers: Int): World =
      val world = stepped("ballpit-4000", 2, workers)
      // Circles now pass through each other: the built-in methods for them are no longer chosen.
      world.detector.asInstanceOf[GridDetector].detectionMethods.prepend { case (_: Circle, _: Circle) => false }
      for _ <- 1 to 5 do world.step()
      world
    StateFingerprint(changed(2)) shouldBe StateFingerprint(changed(1))
  }

  test("two bodies too fast to compute with: under 2 workers the same error as under one, the first pair's") {
    def failure(workers: Int): ArithmeticException =
      val world = stepped("ballpit-4000", 2, workers)
      val balls = world.bodies.filterNot(_.fixed)
      // One early in the world's order and one late: their pairs fall in different ranges.
      for ball <- Seq(balls(balls.size / 8), balls(7 * balls.size / 8)) do ball.linearVelocity = Vector2D(1e160, 0)
      intercept[ArithmeticException](world.step())
    val one = failure(1)
    one.getMessage should include("approach bound")
    failure(2).getMessage shouldBe one.getMessage
  }

  test("more pairs than maxPairs, fewer kept than twice that: under 2 workers the same pairs, or the same error, as under one") {
    // 2,500 balls in a square, each bounds overlapping its 8 neighbours': the kept pairs are
    // emitted in ranges under two workers.
    def world(workers: Int, maxPairs: Int): World =
      val w = World()
      w.enableSleep = false
      w.gravity = Vector2D(0, 0)
      w.solver = SoftStep(workers = workers, maxPairs = maxPairs)
      for i <- 0 until 2500 do
        val ball = Circle(0.5, 1)
        ball.pos = Vector2D(0.99 * (i % 50), 0.99 * (i / 50))
        w += ball.asBody
      w
    def pairs(w: World): Seq[(Int, Int)] =
      val found = w.collisionPipeline.pairs
      (0 until found.size).map(k => (found.first(k).worldIndex, found.second(k).worldIndex))
    val one = world(1, 100000)
    one.step()
    val two = world(2, 100000)
    two.step()
    val count = pairs(one).size
    count should be > 2 * 2048
    pairs(two) shouldBe pairs(one)
    StateFingerprint(two) shouldBe StateFingerprint(one)
    def failure(workers: Int) = intercept[IllegalStateException](world(workers, count - 1).step()).getMessage
    failure(1) should include(s"more than ${count - 1} candidate pairs in one step (the limit SoftStep.maxPairs)")
    failure(2) shouldBe failure(1)
  }

  test("the pairs' shapes and bodies read ahead or not: the same contacts and bits, on one worker and on two") {
    // 2,500 balls in a square, each overlapping its 4 neighbours and in reach of its diagonal ones.
    def stepped(workers: Int, readAheadPairs: Int): World =
      val w = World()
      w.enableSleep = false
      w.gravity = Vector2D(0, -1)
      w.solver = SoftStep(workers = workers)
      for i <- 0 until 2500 do
        val ball = Circle(0.5, 1)
        ball.pos = Vector2D(0.99 * (i % 50), 0.99 * (i / 50))
        w += ball.asBody
      w.workspace(classOf[soft.SoftWorkspace], soft.SoftWorkspace()).finder.readAheadPairs = readAheadPairs
      for _ <- 1 to 5 do w.step()
      w
    val plain = stepped(1, Int.MaxValue)
    val pairs = plain.collisionPipeline.pairs.size
    pairs should be > 2 * 2048 // shared out under two workers
    for workers <- 1 to 2 do StateFingerprint(stepped(workers, 0)) shouldBe StateFingerprint(plain)
  }

  test("workers must be at least 1, named in the error") {
    val error = intercept[IllegalArgumentException](SoftStep(workers = 0))
    error.getMessage should include("workers")
    error.getMessage should include("0")
  }
