package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.PerformanceRegressionSpec.hash
import sims.scenes.Scenes

/** The soft step's `workers`: the same bits for any number of workers, a pool that covers each
  * range once, and threads that stay few however many worlds step.
  */
class SoftStepWorkersSpec extends AnyFunSuite with Matchers:
  import SoftStepWorkersSpec.*

  for (name, steps) <- Cases do
    test(s"$name after $steps steps: the same state under 1, 2, 3 and 4 workers"):
      val hashes = (1 to 4).map(workers => stepped(name, steps, workers))
      hashes.distinct shouldBe hashes.take(1)

  test("the scenes of the workers test have colours large enough to be shared out"):
    // ballpit-2000 after a second: its first colour runs on the threads (more than
    // MinimumPerWorker contacts per worker), so the test above compares threads with the caller.
    val world = Scenes.find("ballpit-2000").get.build().world
    world.solver = SoftStep(workers = 4)
    for _ <- 1 to 60 do world.step()
    val colours = world.workspace(classOf[soft.SoftWorkspace], soft.SoftWorkspace()).passes.colours
    colours.colourSize(0) should be > 4 * Workers.MinimumPerWorker
    colours.colourSize(soft.ContactColours.Count) shouldBe 0

  test("a pool runs every index of a range exactly once, on the caller and its threads"):
    val size = 10007
    val runs = new Array[Int](size)
    val threads = java.util.concurrent.ConcurrentHashMap.newKeySet[String]()
    val task: Workers.Task = (from, until) =>
      threads.add(Thread.currentThread.getName)
      for i <- from until until do runs(i) += 1
    val pool = Workers(3)
    // Until a thread took part (on a busy machine the caller may claim every chunk of a run).
    var rounds = 0
    while rounds < 20 || (threads.size < 2 && rounds < 20000) do
      pool.run(size, task)
      rounds += 1
    runs.distinct.toSeq shouldBe Seq(rounds)
    pool.count shouldBe 3
    threads.size should be > 1

  test("a range too small to share runs on the caller alone"):
    val names = scala.collection.mutable.Set.empty[String]
    Workers(2).run(Workers.MinimumPerWorker, (_, _) => names += Thread.currentThread.getName)
    names shouldBe Set(Thread.currentThread.getName)

  test("one worker is the caller alone: no thread"):
    Workers(1) shouldBe Workers.Serial
    val world = Scenes.find("pyramid-20").get.build().world
    world.solver = SoftStep(workers = 1)
    for _ <- 1 to 5 do world.step()
    workerThreads().filter(_.endsWith("-of-1")) shouldBe empty

  test("200 worlds with workers = 2 share one thread: the live threads stay bounded"):
    // A pool of an earlier class loader (another project's tests in the same JVM) may be alive.
    val poolsBefore = workerThreads().count(_.endsWith("-of-2"))
    val before = Thread.activeCount
    for _ <- 1 to 200 do
      val world = Scenes.find("pyramid-20").get.build().world
      world.solver = SoftStep(workers = 2)
      for _ <- 1 to 3 do world.step()
    workerThreads().count(_.endsWith("-of-2")) should be <= poolsBefore + 1
    // A thread per world would add 200; other suites' background threads may add a few.
    Thread.activeCount should be < before + 10

  test("workers below 1 are refused, naming the argument"):
    val e = intercept[IllegalArgumentException](SoftStep(workers = 0))
    e.getMessage shouldBe "workers must be at least 1, got 0"
    intercept[IllegalArgumentException](Workers(-2)).getMessage should include("workers")

  test("toString names workers when it is not the machine's processors"):
    SoftStep(workers = Workers.available + 1).toString should endWith(s"workers = ${Workers.available + 1})")
    SoftStep().toString should not include "workers"
    SoftStep().workers shouldBe Runtime.getRuntime.availableProcessors

object SoftStepWorkersSpec:
  /** Polygons and circles, contacts and joints (trees and iterative ones); ballpit-2000 and
    * large_pyramid-40 have colours large enough for the threads, the others run on the caller.
    */
  val Cases: Seq[(String, Int)] =
    Seq("pyramid-20" -> 120, "ballpit-2000" -> 90, "chain-100" -> 120, "LimitedRagdoll" -> 150, "Platformer" -> 150,
      "joint_grid-20" -> 60, "large_pyramid-40" -> 60)

  /** The scene stepped under SoftStep with this many workers; its state's hash. */
  def stepped(name: String, steps: Int, workers: Int): String =
    val world = Scenes.find(name).get.build().world
    world.solver = SoftStep(workers = workers)
    for _ <- 1 to steps do world.step()
    hash(world)

  /** The names of the live worker threads. */
  def workerThreads(): Seq[String] =
    Thread.getAllStackTraces.keySet.toArray(Array.empty[Thread]).toSeq.map(_.getName).filter(_.startsWith("sims-worker"))
