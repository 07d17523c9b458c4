package sims.solver

import java.util.concurrent.atomic.{AtomicBoolean, AtomicInteger, AtomicIntegerArray, AtomicLong}
import java.util.concurrent.locks.LockSupport

/** The JVM: pools of daemon threads, one per worker count, made on first use and shared by every
  * world with that count (a program that makes thousands of worlds starts `count - 1` threads,
  * not thousands; they need no closing, being daemons parked while no step runs).
  */
private[solver] object WorkersPlatform:
  private val pools = scala.collection.mutable.HashMap.empty[Int, ThreadPool]

  /** The JVM's available processors. */
  def available: Int = math.max(1, Runtime.getRuntime.availableProcessors)

  /** The pool for `count` workers (made once). */
  def pool(count: Int): Workers = synchronized(pools.getOrElseUpdate(count, ThreadPool(count)))

/** The caller and `count - 1` daemon threads. A `run` hands each thread its range, runs the first
  * range itself and waits for the others: each side spins briefly, then parks (a step's colours
  * follow one another within microseconds; between steps the threads park). Nothing is allocated
  * per `run`. One world's step at a time: a `run` that finds the pool busy (worlds stepped on
  * several threads at once) runs on its caller alone, with the same bits.
  */
private[solver] final class ThreadPool(val count: Int) extends Workers:
  private val busy = AtomicBoolean(false)
  // The work of the current run: written before `epoch` moves on, read after.
  @volatile private var task: Workers.Task = null
  @volatile private var size = 0
  @volatile private var failure: Throwable = null
  private val epoch = AtomicLong(0)
  private val pending = AtomicInteger(0)
  private val parked = AtomicIntegerArray(count)
  private val threads: Array[Thread] = Array.tabulate(count) { w =>
    if w == 0 then null
    else
      val t = Thread(() => work(w), s"sims-worker-$w-of-$count")
      t.setDaemon(true)
      t.start()
      t
  }

  def run(size: Int, task: Workers.Task): Unit =
    if size < Workers.MinimumPerWorker * count || !busy.compareAndSet(false, true) then
      if size > 0 then task.run(0, size)
    else
      try
        // Every worker takes part in every run: none can still be in the last run when the next
        // begins (the caller waited for all), so each reads this run's task and size.
        this.task = task
        this.size = size
        pending.set(count - 1)
        epoch.incrementAndGet()
        var w = 1
        while w < count do
          if parked.get(w) != 0 then LockSupport.unpark(threads(w))
          w += 1
        task.run(0, size / count)
        var spins = 0
        while pending.get != 0 do
          if spins < ThreadPool.Spins then
            Thread.onSpinWait()
            spins += 1
          else Thread.`yield`()
        this.task = null
        val failed = failure
        if failed != null then
          failure = null
          throw failed
      finally busy.set(false)

  private def work(w: Int): Unit =
    var seen = 0L
    while true do
      var spins = 0
      while epoch.get == seen do
        if spins < ThreadPool.Spins then
          Thread.onSpinWait()
          spins += 1
        else
          parked.set(w, 1)
          if epoch.get == seen then LockSupport.park(this)
          parked.set(w, 0)
      seen = epoch.get
      val total = size
      try task.run((total.toLong * w / count).toInt, (total.toLong * (w + 1) / count).toInt)
      catch case e: Throwable => failure = e
      finally pending.decrementAndGet()

  override def toString: String = s"ThreadPool(count = $count)"

private[solver] object ThreadPool:
  /** Spins before parking or yielding: about as long as a colour's work on a small world. */
  val Spins: Int = 20000
