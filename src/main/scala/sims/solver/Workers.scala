package sims.solver

/** Runs a task over a range of indices on one or more workers: the caller's thread and, on the
  * JVM, a pool of threads kept for the worker count (see `SoftStep.workers`).
  *
  * The soft step hands a worker only work that writes its own slots (a colour's contacts share
  * no moving body, a body's integration writes that body), so any split of a range gives the
  * same bits as the caller alone.
  */
trait Workers:
  /** How many workers share a range: the caller and `count - 1` others. */
  def count: Int

  /** Runs `task` over `0 until size`, split into at most `count` contiguous ranges, and returns
    * when every range is done. Small ranges, or a pool busy with another world's step, run on
    * the caller alone.
    */
  def run(size: Int, task: Workers.Task): Unit

/** The worker sets: [[Workers.Serial]], or a platform's pool. */
object Workers:
  /** Work over a range of indices: `run(from, until)` may be called for several disjoint ranges
    * at once, from different threads.
    */
  trait Task:
    /** Does the work of the indices `from` until `until`. */
    def run(from: Int, until: Int): Unit

  /** The caller alone: no thread is started. */
  object Serial extends Workers:
    /** One worker. */
    def count: Int = 1

    /** Runs the whole range on the caller. */
    def run(size: Int, task: Task): Unit = if size > 0 then task.run(0, size)

    override def toString: String = "Workers.Serial"

  /** A range shorter than this many indices per worker runs on the caller alone: handing it out
    * would cost more than it saves.
    */
  val MinimumPerWorker: Int = 128

  /** The processors the platform offers (1 on Scala.js, where there are no threads to share). */
  def available: Int = WorkersPlatform.available

  /** The worker set for `count` workers: [[Serial]] for 1 (no thread), else the platform's pool
    * for that count, made once and shared by every world that asks for the same count.
    */
  def apply(count: Int): Workers =
    if count < 1 then throw IllegalArgumentException(s"workers must be at least 1, got $count")
    if count == 1 then Serial else WorkersPlatform.pool(count)
