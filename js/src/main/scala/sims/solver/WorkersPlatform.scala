package sims.solver

/** Scala.js: one thread, so every worker set is the caller alone (the results are the same). */
private[solver] object WorkersPlatform:
  /** One worker. */
  def available: Int = 1

  /** The caller alone, whatever the count. */
  def pool(count: Int): Workers = Workers.Serial
