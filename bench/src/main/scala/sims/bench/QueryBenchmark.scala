package sims.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import scala.compiletime.uninitialized
import sims.collision.RayHit
import sims.dynamics.{Shape, World}
import sims.geometry.{AABB, Vector2D}
import sims.scenes.Ballpit

/** Time of one world query in a ball pit (16,000 balls by default, as built: a block 10 m wide
  * and 78 m high in its container), cycling through 256 queries of each kind drawn at random
  * inside the pit. The queries' grid is made in the setup; `rebuild` measures taking the
  * bounds again, which the first query after a step pays. `rayCastByScan` is the nearest hit
  * found by casting against every shape, for comparison.
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MICROSECONDS)
class QueryBenchmark:
  /** Balls in the pit. */
  @Param(Array("16000"))
  var balls: Int = uninitialized

  private var world: World = uninitialized
  private var across, down, above: Array[(Vector2D, Vector2D)] = uninitialized
  private var smallBoxes, largeBoxes: Array[AABB] = uninitialized
  private var points: Array[Vector2D] = uninitialized
  private var next = 0

  /** Builds the pit and the queries, and makes the queries' grid. */
  @Setup(Level.Trial)
  def setup(): Unit =
    val pit = Ballpit(balls)
    world = SimsBuilder.world(pit)
    val top = pit.wallTop - 1 // the top of the highest row
    val random = java.util.Random(20261121)
    def within(low: Double, high: Double) = low + random.nextDouble() * (high - low)
    val count = QueryBenchmark.Count
    // From wall to wall at two random heights: the nearest hit is the first ball.
    across = Array.fill(count)((Vector2D(-4.95, within(0, top)), Vector2D(4.95, within(0, top))))
    // From above the pit down to the floor: the nearest hit is the top row.
    down = Array.fill(count)((Vector2D(within(-4.9, 4.9), top + 20), Vector2D(within(-4.9, 4.9), -0.5)))
    // One kilometre above the pit: no hit.
    above = Array.fill(count)((Vector2D(-500, top + 5), Vector2D(500, top + 5 + within(-1, 1))))
    smallBoxes = Array.fill(count) { val c = Vector2D(within(-4.5, 4.5), within(0.5, top)); AABB(c, c + Vector2D(1, 1)) }
    largeBoxes = Array.fill(count) { val c = Vector2D(within(-5, 0), within(0, top - 5)); AABB(c, c + Vector2D(5, 5)) }
    points = Array.fill(count)(Vector2D(within(-4.9, 4.9), within(0.05, top)))
    world.query(smallBoxes(0))

  private def turn(): Int =
    next = (next + 1) & (QueryBenchmark.Count - 1)
    next

  /** The nearest hit of a ray across the pit, wall to wall (10 m, 45 balls on its way). */
  @Benchmark
  def rayCastAcross(): Option[RayHit] = { val (from, to) = across(turn()); world.rayCast(from, to) }

  /** Every hit of a ray across the pit, nearest first. */
  @Benchmark
  def rayCastAllAcross(): IndexedSeq[RayHit] = { val (from, to) = across(turn()); world.rayCastAll(from, to) }

  /** The nearest hit of a ray from 20 m above the pit down to the floor (100 m). */
  @Benchmark
  def rayCastDown(): Option[RayHit] = { val (from, to) = down(turn()); world.rayCast(from, to) }

  /** A 1 km ray passing over the pit, hitting nothing. */
  @Benchmark
  def rayCastMiss(): Option[RayHit] = { val (from, to) = above(turn()); world.rayCast(from, to) }

  /** The shapes overlapping a 1 m box in the pit (about 20). */
  @Benchmark
  def querySmallBox(): IndexedSeq[Shape] = world.query(smallBoxes(turn()))

  /** The shapes overlapping a 5 m box in the pit (about 500). */
  @Benchmark
  def queryLargeBox(): IndexedSeq[Shape] = world.query(largeBoxes(turn()))

  /** The shapes at a point in the pit (0 or 1). */
  @Benchmark
  def shapesAt(): IndexedSeq[Shape] = world.shapesAt(points(turn()))

  /** Taking every shape's bounds again and a small box query: the first query after a step. */
  @Benchmark
  def rebuild(): IndexedSeq[Shape] =
    world.shapesMoved()
    world.query(smallBoxes(turn()))

  /** The nearest hit across the pit by casting against every shape, without the grid. */
  @Benchmark
  def rayCastByScan(): Double =
    val (from, to) = across(turn())
    val shapes = world.shapes
    var nearest = Double.PositiveInfinity
    var i = 0
    while i < shapes.length do
      shapes(i).rayCast(from, to).foreach(hit => nearest = math.min(nearest, hit.fraction))
      i += 1
    nearest

/** Sizes of [[QueryBenchmark]]. */
object QueryBenchmark:
  /** Queries of each kind, cycled through (a power of 2). */
  val Count: Int = 256
