package sims.dynamics

/** The dynamic state of a world: time and, for every body, position, rotation, velocities,
  * force and torque. Restoring it and stepping again replays the run bit for bit.
  */
final class WorldState private ():
  private var bodies = Array.empty[Body]
  private var values = Array.empty[Double]
  private var time = 0.0

  /** Simulated time when the state was taken. */
  def timeOfState: Double = time

  private[sims] def save(world: World): Unit =
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

private[sims] object WorldState:
  private val PerBody = 9
  def empty: WorldState = new WorldState()
