package sims.solver

/** Copies a few doubles with a loop. On the JVM that is as fast as `System.arraycopy`; on
  * Scala.js `System.arraycopy` makes a typed-array view for every call, which costs more than
  * copying the handful of numbers of a joint's row or a contact (a quarter of the soft chain's
  * step in Node).
  */
private[sims] object ShortCopy:
  /** Copies `length` doubles of `from`, starting at `fromIndex`, into `to` at `toIndex`; the
    * two ranges must not overlap.
    */
  inline def doubles(from: Array[Double], fromIndex: Int, to: Array[Double], toIndex: Int, length: Int): Unit =
    var i = 0
    while i < length do
      to(toIndex + i) = from(fromIndex + i)
      i += 1
