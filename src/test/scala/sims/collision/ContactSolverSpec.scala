package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, Shape}
import sims.geometry.Vector2D

/** The world's contact solver must correct velocities exactly as calling each collision's own
  * `correctVelocity` in order would: same order, same arithmetic, same bits.
  */
class ContactSolverSpec extends AnyFunSuite with Matchers:

  /** A collision of a user kind: the solver must leave it to its own `correctVelocity`. */
  private final class UserCollision(a: Circle, b: Circle) extends Collision:
    def shape1: Circle = a
    def shape2: Circle = b
    def normal: Vector2D = (b.pos - a.pos).unit
    def points: Iterable[Vector2D] = List(a.pos + normal * a.radius)

  /** Overlapping balls and a box with velocities, and their collisions of all three kinds. */
  private def scene(): (Seq[Body], IndexedSeq[Collision]) =
    val circles = (0 until 4).map { i =>
      val c = Circle(0.5, 1 + i)
      c.pos = Vector2D(i * 0.9, 0.1 * i)
      c.restitution = 0.3 + 0.1 * i
      c.friction = 0.9 - 0.1 * i
      c
    }
    val box = Rectangle(1, 0.5, 2)
    box.pos = Vector2D(1.4, -0.85)
    box.rotation = 0.1
    val shapes: Seq[Shape] = circles :+ box
    val bodies = shapes.map(_.asBody)
    for (b, i) <- bodies.zipWithIndex do
      b.linearVelocity = Vector2D(1.0 - i, -0.3 * i - 0.5)
      b.angularVelocity = 0.2 * i - 0.3
    val collisions = IndexedSeq(
      CircleCollision(circles(0), circles(1)),
      UserCollision(circles(1), circles(2)),
      PolyCircleCollision(box, circles(1)),
      CircleCollision(circles(2), circles(3)),
      PolyCircleCollision(box, circles(2)))
    (bodies, collisions)

  private def velocityBits(bodies: Seq[Body]): Seq[Long] =
    bodies.flatMap(b => Seq(b.linearVelocity.x, b.linearVelocity.y, b.angularVelocity))
      .map(java.lang.Double.doubleToLongBits)

  test("10 iterations of the solver equal each collision's correctVelocity in order, bit for bit") {
    val h = 1.0 / 60
    val (solved, solvedCollisions) = scene()
    val (reference, referenceCollisions) = scene()
    val before = velocityBits(solved)

    val solver = ContactSolver()
    solver.load(solvedCollisions)
    solver.size shouldBe 5 // one point per built-in kind here, plus the user collision
    for _ <- 1 to 10 do solver.correctVelocities(h)
    for _ <- 1 to 10; c <- referenceCollisions do c.correctVelocity(h)

    velocityBits(solved) should not equal before // the corrections did something
    velocityBits(solved) shouldBe velocityBits(reference)
  }

  test("a cleared solver corrects nothing") {
    val (bodies, collisions) = scene()
    val solver = ContactSolver()
    solver.load(collisions)
    solver.clear()
    val before = velocityBits(bodies)
    solver.correctVelocities(1.0 / 60)
    velocityBits(bodies) shouldBe before
  }
