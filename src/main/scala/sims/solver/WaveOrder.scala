package sims.solver

/** An order for a list of corrections between two bodies each, with the same results as the
  * list's own order and more speed.
  *
  * A contact's correction reads and writes the state of its two bodies only, so two
  * corrections without a common moving body give the same bits in either order. Each
  * correction gets a level (its wave) one above the last level of its bodies' earlier
  * corrections; taking the corrections wave by wave, each wave in list order, keeps every
  * body's corrections in list order, so every body sees the same sequence of arithmetic. The
  * corrections of one wave are independent of each other and the processor can overlap them,
  * where in list order each waits for the one before (a ball's contacts are neighbours in
  * the pair order). Fixed bodies do not order anything: their inverse masses are 0, so a
  * correction only adds zeros to their velocities (the contact solver keeps the list order in
  * the one case where that could show: a fixed body's velocity of -0.0).
  *
  * Use: `clear()`, `add` each correction's body keys in list order, `plan()`, then `apply(k)`
  * is the list index of the k-th correction to run.
  */
private[sims] final class WaveOrder:
  private var count = 0
  // Per correction: the body keys (-1 for a fixed body) and the wave.
  private var keys1, keys2, waveOf = new Array[Int](64)
  private var order = new Array[Int](64)
  // Per body key: the last wave of the body's corrections in the current list (else 0).
  private var lastWave = new Array[Int](64)
  private var waveStart = new Array[Int](64)
  private var _waves = 0

  /** Number of corrections added. */
  def size: Int = count

  /** Number of waves among the corrections added since `clear()`. */
  def waves: Int = _waves

  /** Starts a new list. */
  def clear(): Unit =
    var e = 0
    while e < count do
      if keys1(e) >= 0 then lastWave(keys1(e)) = 0
      if keys2(e) >= 0 then lastWave(keys2(e)) = 0
      e += 1
    count = 0
    _waves = 0

  /** Appends a correction between two bodies given by their keys: small non-negative
    * integers, unique per body (a world's bodies have the keys 0 until n, which their shapes
    * carry), or -1 for a fixed body, which orders nothing.
    */
  def add(key1: Int, key2: Int): Unit =
    if count == order.length then
      val capacity = 2 * count
      keys1 = java.util.Arrays.copyOf(keys1, capacity)
      keys2 = java.util.Arrays.copyOf(keys2, capacity)
      waveOf = java.util.Arrays.copyOf(waveOf, capacity)
      order = java.util.Arrays.copyOf(order, capacity)
    val top = math.max(key1, key2)
    if top >= lastWave.length then lastWave = java.util.Arrays.copyOf(lastWave, math.max(2 * lastWave.length, top + 1))
    val wave = math.max(if key1 < 0 then 0 else lastWave(key1), if key2 < 0 then 0 else lastWave(key2)) + 1
    if key1 >= 0 then lastWave(key1) = wave
    if key2 >= 0 then lastWave(key2) = wave
    keys1(count) = key1
    keys2(count) = key2
    waveOf(count) = wave
    if wave > _waves then _waves = wave
    count += 1

  /** Sorts the corrections by wave (a counting sort, stable within a wave). */
  def plan(): Unit =
    if waveStart.length < _waves + 2 then waveStart = new Array[Int](2 * _waves + 2)
    java.util.Arrays.fill(waveStart, 0, _waves + 2, 0)
    var e = 0
    while e < count do
      waveStart(waveOf(e) + 1) += 1
      e += 1
    var w = 1
    while w <= _waves do
      waveStart(w + 1) += waveStart(w)
      w += 1
    e = 0
    while e < count do
      val to = waveStart(waveOf(e))
      waveStart(waveOf(e)) = to + 1
      order(to) = e
      e += 1

  /** The list index of the k-th correction in wave order (after `plan()`). */
  def apply(k: Int): Int = order(k)
