package sims.dynamics

/** The dynamic state of a world: time; for every body, position, rotation, velocities, force
  * and torque, whether it sleeps (its resting time and island) and whether the user placed it
  * since its last step (a sleeper on it then wakes); what the solvers carry from
  * step to step (the soft step's contact table and its joints' impulses, its warm start); and
  * the pairs of shapes touching and overlapping sensors (the contact and sensor events' open
  * pairs).
  * Restoring it and stepping again replays the run, and its events, bit for bit.
  */
final class WorldState private ():
  import WorldState.{Awake, MovedByUser}
  private var bodies = Array.empty[Body]
  private var values = Array.empty[Double]
  private var time = 0.0
  // Whether `bodies` and `values` hold the bodies of this save (see `begin`); the list saved from.
  private var withBodies = false
  private var list: scala.collection.mutable.ArrayBuffer[Body] = null
  private var joints = Array.empty[sims.dynamics.joints.Joint]
  // For a snapshot: the solvers' carried states, by workspace (null for a step's own save).
  private var carried: Array[AnyRef] = null
  // For a snapshot: the open pairs of the contact and sensor events.
  private var touching: sims.collision.PairTracker.Saved = null
  private var overlapping: sims.collision.PairTracker.Saved = null

  /** Simulated time when the state was taken. */
  def timeOfState: Double = time

  override def toString: String = s"WorldState(time = $time s, ${bodies.length} bodies, ${joints.length} joints)"

  /** Saves the state; with `withSolvers`, copies of what the solvers carry too (a step's own
    * save leaves those to `CarriedState.beginStep`, which copies nothing).
    */
  private[sims] def save(world: World, withSolvers: Boolean = true): Unit =
    begin(world, withSolvers)
    saveAllBodies()

  /** Saves every body of the world given to `begin`. */
  private[sims] def saveAllBodies(): Unit =
    saveBodies(0, bodies.length)
    bodiesSaved()

  /** A step's own save: all but the solvers' carried data, and the bodies unless its solver
    * saves them itself as it reads them (`Solver.savesBodies`).
    */
  private[sims] def saveForStep(world: World): Unit =
    begin(world, withSolvers = false)
    if !world.solver.savesBodies then saveAllBodies()

  /** Saves all but the bodies (see `save`) and makes room for them: `saveBodies` takes them, in
    * one range or several, then `bodiesSaved` says they are all in. Until then `load` leaves the
    * bodies as they are (a solver that saves them as it reads them has not changed them yet).
    */
  private[sims] def begin(world: World, withSolvers: Boolean): Unit =
    saveJoints(world)
    carried =
      if !withSolvers then null
      else world.carriedStates.map(_.copyState()).toArray
    if withSolvers then
      touching = world.contactTracker.openPairs()
      overlapping = world.sensorTracker.openPairs()
    list = world.bodyList
    if bodies.length != list.length then
      bodies = new Array[Body](list.length)
      values = new Array[Double](list.length * WorldState.PerBody)
    time = world.time
    withBodies = false

  /** Saves bodies `from` until `until` of the world given to `begin`. Writes their slots only:
    * ranges may be saved on several threads at once.
    */
  private[sims] def saveBodies(from: Int, until: Int): Unit =
    var i = from
    while i < until do
      saveBody(i, list(i))
      i += 1

  /** Saves body `b`, number i of the world given to `begin`. */
  private[sims] def saveBody(i: Int, b: Body): Unit =
    if bodies(i) ne b then bodies(i) = b // no write barrier for the same body as last time
    val k = i * WorldState.PerBody
    values(k) = b.x; values(k + 1) = b.y; values(k + 2) = b.angle
    values(k + 3) = b.vx; values(k + 4) = b.vy; values(k + 5) = b.w
    values(k + 6) = b.fx; values(k + 7) = b.fy; values(k + 8) = b.tau
    values(k + 9) = (if b.isAwake then Awake else 0) + (if b.movedByUser then MovedByUser else 0)
    values(k + 10) = b.sleepTime
    values(k + 11) = b.sleepIsland.toDouble // exact: island numbers stay far below 2^53

  /** Every body is saved (see `begin`). */
  private[sims] def bodiesSaved(): Unit =
    list = null
    withBodies = true

  private[sims] def load(world: World): Unit =
    val bs = world.bodies
    if withBodies && (bs.length != bodies.length || bs.indices.exists(i => bs(i) ne bodies(i))) then
      throw IllegalArgumentException("state was taken of a world with other bodies")
    val js = world.joints
    if js.length != joints.length || js.indices.exists(i => js(i) ne joints(i)) then
      throw IllegalArgumentException("state was taken of a world with other joints")
    if carried != null then
      // Solvers the world took up after the snapshot start again from nothing.
      val states = world.carriedStates
      var k = 0
      while k < states.length do
        states(k).restoreState(if k < carried.length then carried(k) else null)
        k += 1
      world.restoreEvents(touching, overlapping)
    world.time = time
    var i = 0
    while withBodies && i < bodies.length do
      val b = bodies(i)
      val k = i * WorldState.PerBody
      b.x = values(k); b.y = values(k + 1); b.angle = values(k + 2)
      b.vx = values(k + 3); b.vy = values(k + 4); b.w = values(k + 5)
      b.fx = values(k + 6); b.fy = values(k + 7); b.tau = values(k + 8)
      val flags = values(k + 9).toInt
      b.restoreSleep((flags & Awake) != 0, values(k + 10), values(k + 11).toLong)
      b.movedByUser = (flags & MovedByUser) != 0
      b.placeShapes()
      // Islands numbered after it stay apart from the restored ones.
      if b.sleepIsland >= world.sleepIslands && b.sleepIsland != Long.MaxValue then world.sleepIslands = b.sleepIsland
      i += 1
    // The next soft step collides its pairs again, even if every body sleeps.
    world.revision += 1

  /** The joints of the world, to check that a restored world has the same ones. */
  private def saveJoints(world: World): Unit =
    val js = world.jointList
    if joints.length != js.length then joints = new Array(js.length)
    var i = 0
    while i < js.length do
      if joints(i) ne js(i) then joints(i) = js(i) // no write barrier for last step's joint
      i += 1

private[sims] object WorldState:
  private val PerBody = 12
  // A body's flags, in its value 9: awake; placed by the user since its last soft step.
  private inline val Awake = 1
  private inline val MovedByUser = 2
  def empty: WorldState = new WorldState()
