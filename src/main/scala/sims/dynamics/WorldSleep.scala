package sims.dynamics

/** A world's sleeping: whether bodies may fall asleep, the islands' numbers, waking, and the
  * count of changes a sleeping world must see (the islands themselves are the soft step's).
  */
trait WorldSleep:
  this: World =>

  private var _enableSleep = true
  /** The last sleeping island's number (see `Body.isAwake`). */
  private[sims] var sleepIslands: Long = 0
  /** Counts the changes a sleeping world must see: bodies and joints added or removed, fixed
    * bodies moved by the user. A soft step in which every body sleeps skips its collision
    * stage only while the count is what it was at the last full step.
    */
  private[sims] var revision: Long = 0

  /** Whether bodies may fall asleep (default true): islands of touching or jointed bodies
    * that have rested for `Defaults.TimeToSleep` stop being simulated until something wakes
    * them (see `Body.isAwake` and docs/two-solvers.md, Sleeping). Only the soft step puts bodies to sleep.
    * Turning it off wakes every body.
    */
  def enableSleep: Boolean = _enableSleep

  /** Lets islands fall asleep, or wakes every body and keeps them awake. */
  def enableSleep_=(value: Boolean): Unit =
    _enableSleep = value
    if !value then wakeAll()

  /** Number of bodies awake (fixed bodies count as awake). */
  def awakeBodyCount: Int = bodyList.count(_.isAwake)

  /** A new sleeping island's number. */
  private[sims] def newSleepIsland(): Long =
    sleepIslands += 1
    sleepIslands

  /** Wakes every body asleep in `island`. */
  private[sims] def wakeIsland(island: Long): Unit =
    var i = 0
    while i < bodyList.length do
      val b = bodyList(i)
      if !b.isAwake && b.sleepIsland == island then b.wakeAlone()
      i += 1

  /** Wakes every body. */
  private[sims] def wakeAll(): Unit =
    var i = 0
    while i < bodyList.length do
      bodyList(i).wakeAlone()
      i += 1

  /** A fixed body was placed by the user: the next soft step wakes what sleeps on it. */
  private[sims] def fixedBodyMoved(): Unit = revision += 1

  /** A shape's contact-event switch changed: the next step looks at every pair again. */
  private[sims] def eventSwitchChanged(): Unit = revision += 1
