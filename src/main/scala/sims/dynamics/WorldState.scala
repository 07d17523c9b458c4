package sims.dynamics

/** The dynamic state of a world: time; for every body, position, rotation, velocities, force
  * and torque; what the solvers carry from step to step (the soft step's contact table and its
  * joints' impulses, its warm start); and the pairs of shapes touching and overlapping sensors
  * (the contact and sensor events' open pairs).
  * Restoring it and stepping again replays the run, and its events, bit for bit.
  */
final class WorldState private ():
  private var bodies = Array.empty[Body]
  private var values = Array.empty[Double]
  private var time = 0.0
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
    saveJoints(world)
    carried =
      if !withSolvers then null
      else world.carriedStates.map(_.copyState()).toArray
    if withSolvers then
      touching = world.contactTracker.openPairs()
      overlapping = world.sensorTracker.openPairs()
    val bs = world.bodies
    if bodies.length != bs.length then
      bodies = new Array[Body](bs.length)
      values = new Array[Double](bs.length * WorldState.PerBody)
    time = world.time
    var i = 0
    while i < bs.length do
      val b = bs(i)
      bodies(i) = b
      val k = i * WorldState.PerBody
      values(k) = b.x; values(k + 1) = b.y; values(k + 2) = b.angle
      values(k + 3) = b.vx; values(k + 4) = b.vy; values(k + 5) = b.w
      values(k + 6) = b.fx; values(k + 7) = b.fy; values(k + 8) = b.tau
      i += 1

  private[sims] def load(world: World): Unit =
    val bs = world.bodies
    if bs.length != bodies.length || bs.indices.exists(i => bs(i) ne bodies(i)) then
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
    while i < bodies.length do
      val b = bodies(i)
      val k = i * WorldState.PerBody
      b.x = values(k); b.y = values(k + 1); b.angle = values(k + 2)
      b.vx = values(k + 3); b.vy = values(k + 4); b.w = values(k + 5)
      b.fx = values(k + 6); b.fy = values(k + 7); b.tau = values(k + 8)
      b.placeShapes()
      i += 1

  /** The joints of the world, to check that a restored world has the same ones. */
  private def saveJoints(world: World): Unit =
    val js = world.jointList
    if joints.length != js.length then joints = new Array(js.length)
    var i = 0
    while i < js.length do
      joints(i) = js(i)
      i += 1

private[sims] object WorldState:
  private val PerBody = 9
  def empty: WorldState = new WorldState()
