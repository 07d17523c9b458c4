package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Circle, Rectangle, Shape, World}
import sims.geometry.{AABB, Projection, Vector2D}

/** A user's own shape with its own narrowphase methods appended to the detector's lists. */
class ExtensionSpec extends AnyFunSuite with Matchers:

  /** A horizontal half plane below y = level, as a (huge but finite) user shape. */
  final class Floor(val level: Double) extends Shape:
    val density = 1.0
    val volume = 1.0
    val I = 1.0
    def AABB: AABB = new sims.geometry.AABB(Vector2D(-1e3, level - 1), Vector2D(1e3, level))
    def project(axis: Vector2D): Projection =
      val ends = Seq(Vector2D(-1e3, level), Vector2D(1e3, level), Vector2D(-1e3, level - 1), Vector2D(1e3, level - 1))
      val ps = ends.map(_ dot axis)
      Projection(axis, ps.min, ps.max)
    def contains(point: Vector2D): Boolean = point.y <= level && point.y >= level - 1

  /** Contact of a circle with the floor: normal up, point under the centre. */
  final class FloorCollision(floor: Floor, circle: Circle) extends Collision:
    val shape1: Shape = floor
    val shape2: Shape = circle
    val normal: Vector2D = Vector2D(0, 1)
    val points: Iterable[Vector2D] = List(Vector2D(circle.pos.x, floor.level))

  private def worldWithFloor(): (World, GridDetector) =
    val world = World()
    val detector = world.detector.asInstanceOf[GridDetector]
    detector.detectionMethods += { case (f: Floor, c: Circle) => c.pos.y - c.radius <= f.level }
    detector.collisionMethods += { case (f: Floor, c: Circle) => FloorCollision(f, c) }
    val floor = Floor(0).asBody
    floor.fixed = true
    world += floor
    (world, detector)

  test("a ball comes to rest on a user-defined floor through user-appended methods") {
    val (world, _) = worldWithFloor()
    val ball = Circle(0.2, 1)
    ball.pos = Vector2D(0, 1)
    ball.restitution = 0
    world += ball.asBody
    for _ <- 1 to 180 do world.step()
    ball.pos.y shouldBe 0.2 +- 0.015
    world.collisions.head shouldBe a[FloorCollision]
  }

  test("a method appended after the first step is seen") {
    val world = World()
    val floor = Floor(0).asBody
    floor.fixed = true
    world += floor
    val ball = Circle(0.2, 1)
    ball.pos = Vector2D(0, 0.1)
    world += ball.asBody
    val error = intercept[IllegalStateException](world.step())
    error.getMessage should include("Floor")
    error.getMessage should include("Circle")
    val detector = world.detector.asInstanceOf[GridDetector]
    detector.detectionMethods += { case (f: Floor, c: Circle) => c.pos.y - c.radius <= f.level }
    detector.collisionMethods += { case (f: Floor, c: Circle) => FloorCollision(f, c) }
    world.step()
    world.collisions.size shouldBe 1
  }

  test("a pair no method covers fails naming both shape classes") {
    val (world, _) = worldWithFloor()
    val box = Rectangle(0.5, 0.5, 1)
    box.pos = Vector2D(0, 0.4)
    world += box.asBody
    val error = intercept[IllegalStateException](world.step())
    error.getMessage should include("Floor")
    error.getMessage should include("Rectangle")
  }
