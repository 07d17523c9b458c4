package sims.solver

/** Runs numbered tasks on one or more workers: the caller's thread and, on the JVM, a pool of
  * threads kept for the worker count (see `SoftStep.workers`).
  *
  * The soft step hands the workers only tasks that write slots of their own (a block of
  * contacts that shares no moving body with the other blocks run at the same time, a range of
  * bodies), so the bits never depend on how many workers there are or which one ran a task.
  */
trait Workers:
  /** How many workers share the tasks: the caller and `count - 1` others. */
  def count: Int

  /** Runs `task` for each index in `0 until tasks` and returns when every one is done. On a
    * pool busy with another world's step, the caller runs them all alone.
    */
  def run(tasks: Int, task: Workers.Task): Unit

/** The worker sets: [[Workers.Serial]], or a platform's pool. */
object Workers:
  /** One numbered task: `run(index)` may be called for several indices at once, from
    * different threads.
    */
  trait Task:
    /** Does the work of task `index`. */
    def run(index: Int): Unit

  /** The caller alone: no thread is started. */
  object Serial extends Workers:
    /** One worker. */
    def count: Int = 1

    /** Runs every task on the caller, in order. */
    def run(tasks: Int, task: Task): Unit =
      var i = 0
      while i < tasks do
        task.run(i)
        i += 1

    override def toString: String = "Workers.Serial"

  /** Where range `index` (0 to `ranges`) starts when `items` items are cut into `ranges` ranges of
    * about equal size: items * index / ranges, in Int arithmetic when the product fits (on
    * Scala.js a Long's division allocates).
    */
  private[sims] def rangeStart(items: Int, ranges: Int, index: Int): Int =
    if items <= Int.MaxValue / ranges then items * index / ranges else (items.toLong * index / ranges).toInt

  /** The processors the platform offers (1 on Scala.js, which has one thread). */
  def available: Int = WorkersPlatform.available

  /** The worker set for `count` workers: [[Serial]] for 1 (no thread), else the platform's pool
    * for that count, made once and shared by every world that asks for the same count.
    */
  def apply(count: Int): Workers =
    if count < 1 then throw IllegalArgumentException(s"workers must be at least 1, got $count")
    if count == 1 then Serial else WorkersPlatform.pool(count)
