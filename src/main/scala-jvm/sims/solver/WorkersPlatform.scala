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

/** The caller and `count - 1` daemon threads. The tasks of a `run` are claimed one by one by the
  * caller and the threads, so a thread the machine has not scheduled yet costs nothing: the
  * caller claims the tasks itself and waits only for those under way on other threads. The
  * caller claims from the first task on, the threads from the last one back: runs over the same
  * blocks (a step's passes) then give each thread much the same tasks every time, whose data its
  * core's cache still holds. Between
  * runs the threads spin briefly, then park (a step's runs follow one another within
  * microseconds; between steps the threads park). Nothing is allocated per `run`. One world's
  * step at a time: a `run` that finds the pool busy (worlds stepped on several threads at once)
  * runs on its caller alone, with the same bits.
  */
private[solver] final class ThreadPool(val count: Int) extends Workers:
  import ThreadPool.*

  private val busy = AtomicBoolean(false)
  // The work of the current run: written before `claims` announces the run, read after.
  @volatile private var task: Workers.Task = null
  @volatile private var failure: Throwable = null
  // The run's number, the end of the tasks left (one past the last) and the first task left, in
  // one value: a claim succeeds only within the run it read (a thread late for one run cannot
  // take the next one's tasks).
  private val claims = AtomicLong(0)
  private val done = AtomicInteger(0)
  private val parked = AtomicIntegerArray(count)
  private var runs = 0L
  private val threads: Array[Thread] = Array.tabulate(count) { w =>
    if w == 0 then null
    else
      val t = Thread(() => work(w), s"sims-worker-$w-of-$count")
      t.setDaemon(true)
      t.start()
      t
  }

  def run(tasks: Int, task: Workers.Task): Unit =
    if tasks <= 1 || tasks > TaskMask || !busy.compareAndSet(false, true) then Workers.Serial.run(tasks, task)
    else
      try
        this.task = task
        done.set(0)
        runs = (runs + 1) & RunMask
        claims.set(runs << RunShift | tasks.toLong << TaskShift)
        var w = 1
        while w < count do
          if parked.get(w) != 0 then LockSupport.unpark(threads(w))
          w += 1
        claimAll(fromEnd = false)
        var spins = 0
        while done.get != tasks do
          if spins < Spins then
            Thread.onSpinWait()
            spins += 1
          else Thread.`yield`()
        this.task = null
        val failed = failure
        if failed != null then
          failure = null
          throw failed
      finally busy.set(false)

  // Claims and runs tasks of the run announced in `claims` until none is left: the first task
  // left each time, or (`fromEnd`) the last.
  private def claimAll(fromEnd: Boolean): Unit =
    var claiming = true
    while claiming do
      val seen = claims.get
      val end = ((seen >>> TaskShift) & TaskMask).toInt
      val first = (seen & TaskMask).toInt
      if first >= end then claiming = false
      else
        // Read before the claim: while tasks are left, the run (and so its task) is this one.
        val t = task
        val index = if fromEnd then end - 1 else first
        if claims.compareAndSet(seen, if fromEnd then seen - (1L << TaskShift) else seen + 1) then
          try t.run(index)
          catch case e: Throwable => failure = e
          finally done.incrementAndGet()

  private def work(w: Int): Unit =
    var seenRun = 0L
    while true do
      var spins = 0
      while (claims.get >>> RunShift) == seenRun do
        if spins < Spins then
          Thread.onSpinWait()
          spins += 1
        else
          parked.set(w, 1)
          if (claims.get >>> RunShift) == seenRun then LockSupport.park(this)
          parked.set(w, 0)
      seenRun = claims.get >>> RunShift
      claimAll(fromEnd = true)

  override def toString: String = s"ThreadPool(count = $count)"

private[solver] object ThreadPool:
  /** Spins before parking or yielding: about as long as a block of contacts on a small world. */
  val Spins: Int = 20000
  private val TaskShift = 20
  private val RunShift = 40
  private val TaskMask = (1L << TaskShift) - 1
  private val RunMask = (1L << (63 - RunShift)) - 1
