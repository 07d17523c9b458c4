package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The worker sets run every task of a run once, whoever claims it (the caller from the first
  * task, the pool's threads from the last), hand a task's failure to the caller, and take the
  * next run after it.
  */
class WorkersSpec extends AnyFunSuite with Matchers:
  /** Runs `tasks` tasks `rounds` times on `workers`; how many times each index ran, per round. */
  private def hits(workers: Workers, tasks: Int, rounds: Int): Seq[Seq[Int]] =
    for _ <- 1 to rounds yield
      val counts = new Array[Int](tasks)
      workers.run(tasks, index => counts(index) += 1)
      counts.toSeq

  for count <- 1 to 4; tasks <- Seq(1, 2, 3, 8, 15, 1000) do
    test(s"$count workers, $tasks tasks: every task runs once in every run") {
      hits(Workers(count), tasks, rounds = 200).foreach(_ shouldBe Seq.fill(tasks)(1))
    }

  test("a task's failure reaches the caller, and the workers take the next run") {
    val workers = Workers(2)
    val error = intercept[IllegalStateException](
      workers.run(8, index => if index == 5 then throw IllegalStateException("task 5")))
    error.getMessage shouldBe "task 5"
    hits(workers, 8, rounds = 20).foreach(_ shouldBe Seq.fill(8)(1))
  }
