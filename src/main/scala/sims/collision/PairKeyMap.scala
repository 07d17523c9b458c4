package sims.collision

/** A map from a shape pair's key (a Long, see [[PairTracker]]) to an Int, by open addressing,
  * emptied in constant time (each slot carries the generation it was written in). Lookups
  * depend on the key alone, never on the order of insertion, and nothing iterates over it: what
  * uses it stays deterministic. Allocation-free except when it grows.
  */
private[sims] final class PairKeyMap:
  private var keys = new Array[Long](64)
  private var values = new Array[Int](64)
  private var written = new Array[Int](64)
  private var generation = 1
  private var mask = 63
  private var count = 0

  /** Number of keys. */
  def size: Int = count

  /** Forgets every key. */
  def clear(): Unit =
    count = 0
    if generation == Int.MaxValue then
      java.util.Arrays.fill(written, 0)
      generation = 1
    else generation += 1

  /** The value of `key`, or -1 if it has none. */
  def get(key: Long): Int =
    var slot = PairKeyMap.hash(key) & mask
    while written(slot) == generation && keys(slot) != key do slot = (slot + 1) & mask
    if written(slot) == generation then values(slot) else -1

  /** Gives `key` the value `value` (replacing its old one). */
  def put(key: Long, value: Int): Unit =
    if 2 * (count + 1) > keys.length then grow()
    var slot = PairKeyMap.hash(key) & mask
    while written(slot) == generation && keys(slot) != key do slot = (slot + 1) & mask
    if written(slot) != generation then
      written(slot) = generation
      keys(slot) = key
      count += 1
    values(slot) = value

  private def grow(): Unit =
    val (oldKeys, oldValues, oldWritten, oldGeneration) = (keys, values, written, generation)
    keys = new Array[Long](2 * oldKeys.length)
    values = new Array[Int](keys.length)
    written = new Array[Int](keys.length)
    mask = keys.length - 1
    generation = 1
    count = 0
    var i = 0
    while i < oldKeys.length do
      if oldWritten(i) == oldGeneration then put(oldKeys(i), oldValues(i))
      i += 1

private object PairKeyMap:
  private inline def hash(key: Long): Int =
    val h = key * 0x9e3779b97f4a7c15L
    (h ^ (h >>> 29)).toInt
