package sims.collision

import sims.dynamics.Shape

/** The key of a pair of shapes, the same for every table of pairs (contacts, events): the two
  * shapes' join orders (`worldIndex`, never reused), the first's in the high half. Keys sort in
  * the shapes' world order, so whatever is sorted by key is in a deterministic order.
  */
private[sims] object PairKey:
  /** The key of the pair (first, second). */
  inline def of(first: Shape, second: Shape): Long = (first.worldIndex.toLong << 32) | (second.worldIndex.toLong & 0xffffffffL)

  /** How far from its starting place `near` looks, each way. */
  inline val NearReach = 32

  /** The place of `key` in `keys(0 until count)` among the `NearReach` from `from` on, else among
    * the `NearReach` before `from`; -1 if in neither. For lists of pairs in last step's order:
    * the pairs come in much the same order every step, but a pair that began or ended shifts the
    * rest, and pairs met in another order swap places.
    */
  def near(keys: Array[Long], count: Int, from: Int, key: Long): Int =
    val end = math.min(from + NearReach, count)
    var p = from
    while p < end && keys(p) != key do p += 1
    if p < end then p
    else
      val start = from - NearReach
      p = math.min(from, count) - 1
      while p >= 0 && p >= start && keys(p) != key do p -= 1
      if p >= 0 && p >= start then p else -1
