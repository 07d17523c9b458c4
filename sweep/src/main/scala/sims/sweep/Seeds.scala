package sims.sweep

/** Seeds and uniform numbers derived from a sweep's seed and a run's index alone, so that a run
  * draws the same numbers on any back end, thread or machine (SplitMix64's finaliser, written
  * out here so that no JDK version can change the numbers).
  */
object Seeds:
  private val Golden = 0x9e3779b97f4a7c15L
  private val Unit = 1.0 / (1L << 53)

  /** A well-mixed 64-bit value of `value` (SplitMix64's finaliser). */
  def mix(value: Long): Long =
    var z = value
    z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L
    z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL
    z ^ (z >>> 31)

  /** The seed of run `index` of a sweep seeded with `seed`. */
  def ofRun(seed: Long, index: Int): Long = mix(seed + Golden * (index.toLong + 1))

  /** The `k`-th uniform number in [0, 1) of the stream seeded with `seed` (53 random bits). */
  def uniform(seed: Long, k: Int): Double = (mix(seed ^ mix(Golden * (k.toLong + 1))) >>> 11) * Seeds.Unit
