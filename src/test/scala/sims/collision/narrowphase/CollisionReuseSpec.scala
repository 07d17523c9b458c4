package sims.collision.narrowphase

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.collision.GridDetector
import sims.dynamics.{Circle, Rectangle, Shape, World}
import sims.geometry.Vector2D

/** The narrowphase's reuse of collision objects: a polygon contact that ends gives its object
  * to the next polygon contact, in whatever pair slot that one is, instead of each slot making
  * its own.
  */
class CollisionReuseSpec extends AnyFunSuite with Matchers:

  private def ball(x: Double, y: Double): Circle =
    val c = Circle(0.5, 1); c.pos = Vector2D(x, y); c.asBody; c

  private def slotFor(cache: Narrowphase, a: Shape, b: Shape): PairSlot =
    val slot = PairSlot()
    slot.first = a
    slot.second = b
    slot.methods = cache.resolve(a, b)
    slot

  private def readyCache(): Narrowphase =
    val detector = GridDetector(World())
    val cache = Narrowphase()
    cache.update(detector.detectionMethods, detector.collisionMethods)
    cache

  test("a polygon-circle contact that ends hands its collision object to the next one") {
    val cache = readyCache()
    val floor = Rectangle(5, 0.5, 1); floor.pos = Vector2D(0, 0); floor.asBody.fixed = true
    val a = ball(-2, 0.9) // 0.1 m into the floor
    val b = ball(2, 3) // well above it
    val slotA = slotFor(cache, floor, a)
    val slotB = slotFor(cache, floor, b)

    val first = cache.collide(slotA)
    first should not be null
    cache.collide(slotB) shouldBe null

    a.body.pos = Vector2D(-2, 3) // a leaves the floor: its slot gives the object back
    cache.collide(slotA) shouldBe null
    b.body.pos = Vector2D(2, 0.9) // b lands: it gets that object, refilled for its own pair
    val second = cache.collide(slotB)
    second should be theSameInstanceAs first
    second.shape2 should be theSameInstanceAs b
    second.points.head.y shouldBe 0.4 +- 1e-12 // b's lowest point, 0.1 m into the floor
  }

  test("a slot whose pair is of another kind gives back its polygon objects") {
    val cache = readyCache()
    val floor = Rectangle(5, 0.5, 1); floor.pos = Vector2D(0, 0); floor.asBody.fixed = true
    val a = ball(0, 0.9)
    val slot = slotFor(cache, floor, a)
    val made = cache.collide(slot)
    made should not be null
    cache.releaseUnused(slot, PairKind.CircleCircle) // the slot now holds two circles
    slot.polyCircle shouldBe null
    val other = slotFor(cache, floor, ball(3, 0.9))
    cache.collide(other) should be theSameInstanceAs made
  }
