package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.collision.narrowphase.{BuiltInMethods, Narrowphase}
import sims.dynamics.{Shape, World}

/** The sensor stage, after each step: for every sensor shape of a world, the shapes overlapping
  * it now, reported to the sensors' [[PairTracker]]. The candidates come from the world's query
  * grid (the shapes whose bounds overlap the sensor's), never from a scan of every shape; each is
  * kept if [[PairFilter.sensorSees]] accepts it and the narrowphase's test (the detector's
  * `detectionMethods`, the built-in ones for a detector of another kind) says the two overlap.
  */
private[sims] final class SensorOverlaps:
  private val narrowphase = Narrowphase()
  private val builtInTests = ArrayBuffer.from(BuiltInMethods.tests)
  private val builtInCollisions = ArrayBuffer.from(BuiltInMethods.collisions)
  private val found = ArrayBuffer.empty[Shape]

  /** Reports every overlap of the sensors of `world` (`sensors`, in world order) to `tracker`. */
  def find(world: World, sensors: collection.IndexedSeq[Shape], tracker: PairTracker): Unit =
    world.detector match
      case grid: GridDetector => narrowphase.update(grid.detectionMethods, grid.collisionMethods)
      case _ => narrowphase.update(builtInTests, builtInCollisions)
    var i = 0
    while i < sensors.length do
      val sensor = sensors(i)
      if sensor.collidable then
        found.clear()
        world.shapesNear(sensor.minX, sensor.minY, sensor.maxX, sensor.maxY, found)
        var k = 0
        while k < found.length do
          val visitor = found(k)
          if PairFilter.sensorSees(sensor, visitor) && overlap(sensor, visitor) then tracker.touch(sensor, visitor)
          k += 1
      i += 1

  /** The narrowphase's test of the two shapes, the one that joined the world first first (the
    * order the detector asks its methods in).
    */
  private def overlap(sensor: Shape, visitor: Shape): Boolean =
    if sensor.worldIndex < visitor.worldIndex then narrowphase.test(narrowphase.resolve(sensor, visitor), sensor, visitor)
    else narrowphase.test(narrowphase.resolve(visitor, sensor), visitor, sensor)
