package sims

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, World}
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

/** Golden hashes of whole simulations, recorded with the straightforward implementation
  * before any speed work: optimisations of the step (solver, narrowphase, broadphase) must
  * keep every body's doubles bit for bit. A changed hash means the floating-point results
  * changed; it must never be updated silently.
  */
class PerformanceRegressionSpec extends AnyFunSuite with Matchers:
  import PerformanceRegressionSpec.*

  test("a ballpit of 300 balls in a container: bit-identical after 240 steps") {
    val world = ballpit(300)
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "b8df93bf8445044d"
  }

  test("a pyramid of 12 rows of boxes: bit-identical after 240 steps") {
    val world = pyramid(12)
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "7cd60b3d14c6e925"
  }

  test("mixed shapes, a two-shape body and a chain: bit-identical after 240 steps") {
    val world = mixed()
    for _ <- 1 to 240 do world.step()
    hash(world) shouldBe "4de67497cc14680b"
  }

/** The golden scenes and the hash. */
object PerformanceRegressionSpec:
  /** A hex digest of every body's position, rotation and velocities, in world order. */
  def hash(world: World): String =
    val digest = java.security.MessageDigest.getInstance("SHA-256")
    val buffer = java.nio.ByteBuffer.allocate(8 * 6)
    for b <- world.bodies do
      buffer.clear()
      buffer.putDouble(b.pos.x).putDouble(b.pos.y).putDouble(b.rotation)
      buffer.putDouble(b.linearVelocity.x).putDouble(b.linearVelocity.y).putDouble(b.angularVelocity)
      digest.update(buffer.array())
    digest.digest().take(8).map(byte => f"${byte & 0xff}%02x").mkString

  private def fixedBox(x: Double, y: Double, halfWidth: Double, halfHeight: Double): Body =
    val r = Rectangle(halfWidth, halfHeight, 1)
    r.pos = Vector2D(x, y)
    r.friction = math.sqrt(0.5)
    r.restitution = 0
    val b = r.asBody
    b.fixed = true
    b

  /** Balls of radius 0.1 on a jittered grid (20 per row) in a container 4.5 m wide. */
  def ballpit(n: Int): World =
    val world = World()
    world += fixedBox(0, -0.5, 3.5, 0.5)
    world += fixedBox(-2.75, 5, 0.5, 5)
    world += fixedBox(2.75, 5, 0.5, 5)
    val random = java.util.Random(7)
    for i <- 0 until n do
      val c = Circle(0.1, 1)
      c.pos = Vector2D(-2.2 + (i % 20) * 0.22 + (random.nextDouble() * 2 - 1) * 0.005, 0.12 + (i / 20) * 0.22)
      c.friction = math.sqrt(0.5)
      c.restitution = 0
      world += c.asBody
    world

  /** A pyramid of 0.5 m boxes on a fixed ground. */
  def pyramid(rows: Int): World =
    val world = World()
    world += fixedBox(0, -0.5, 40, 0.5)
    for row <- 0 until rows; j <- 0 until rows - row do
      val r = Rectangle(0.25, 0.25, 1)
      r.pos = Vector2D((j - (rows - row - 1) / 2.0) * 0.5625, 0.25 + row * 0.5)
      r.friction = math.sqrt(0.5)
      r.restitution = 0
      world += r.asBody
    world

  /** Triangles, hexagons, circles, a rotated box, a body of two shapes and a short chain
    * hanging from a fixed ball, dropped into a container with default materials.
    */
  def mixed(): World =
    val world = World()
    world += fixedBox(0, -0.5, 4, 0.5)
    world += fixedBox(-3.5, 3, 0.5, 3)
    world += fixedBox(3.5, 3, 0.5, 3)
    for i <- 0 until 24 do
      val x = -2.5 + (i % 6) * 0.9
      val y = 0.6 + (i / 6) * 0.9
      val shape = i % 4 match
        case 0 => RegularPolygon(3, 0.3, 1)
        case 1 => RegularPolygon(6, 0.3, 2)
        case 2 => Circle(0.25, 1)
        case _ =>
          val r = Rectangle(0.3, 0.15, 1)
          r.rotation = 0.3 * i
          r
      shape.pos = Vector2D(x, y)
      world += shape.asBody
    val left = Circle(0.2, 1)
    left.pos = Vector2D(-1, 5)
    val right = Rectangle(0.3, 0.1, 1)
    right.pos = Vector2D(-0.5, 5.1)
    right.rotation = 0.5
    world += Body(left, right)
    val anchor = Circle(0.05, 1)
    anchor.pos = Vector2D(1.5, 5.5)
    val fixed = anchor.asBody
    fixed.fixed = true
    world += fixed
    var previous = fixed
    for i <- 1 to 5 do
      val link = Circle(0.08, 1)
      link.pos = Vector2D(1.5 + 0.3 * i, 5.5)
      val b = link.asBody
      world += b
      world += DistanceJoint(previous, previous.pos, b, b.pos)
      previous = b
    world
