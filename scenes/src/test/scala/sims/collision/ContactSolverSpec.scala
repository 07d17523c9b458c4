package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, Shape}
import sims.geometry.Vector2D
import sims.scenes.BallStack
import sims.solver.ContactSolver

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

  /** Loads the first scene's collisions into a solver, lets `check` look at it, runs 10
    * iterations, and expects the bits of 10 rounds of the second (identical) scene's
    * collisions, each corrected by its own `correctVelocity` in list order.
    */
  private def solvesLikeListOrder(solved: (Seq[Body], IndexedSeq[Collision]),
      reference: (Seq[Body], IndexedSeq[Collision]))(check: ContactSolver => Unit): Unit =
    val h = 1.0 / 60
    val before = velocityBits(solved._1)
    val solver = ContactSolver()
    solver.load(solved._2)
    check(solver)
    for _ <- 1 to 10 do solver.correctVelocities(h)
    for _ <- 1 to 10; c <- reference._2 do c.correctVelocity(h)
    velocityBits(solved._1) should not equal before // the corrections did something
    velocityBits(solved._1) shouldBe velocityBits(reference._1)

  test("10 iterations of the solver equal each collision's correctVelocity in order, bit for bit") {
    solvesLikeListOrder(scene(), scene()) { solver =>
      solver.size shouldBe 5 // one point per built-in kind here, plus the user collision
    }
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

  /** A world's pile of balls in a container after a second of falling, with its bodies and
    * its collisions just detected.
    */
  private def pile(): (Seq[Body], IndexedSeq[Collision]) =
    val (world, _) = BallStack.withBalls(60)
    for _ <- 1 to 60 do world.step()
    world.detector.detect()
    (world.bodies.toSeq, world.detector.collisions.toIndexedSeq)

  test("in a world's pile the solver runs in waves, with the bits of each collision in list order") {
    solvesLikeListOrder(pile(), pile()) { solver =>
      solver.size should be > 60
      solver.waveCount should be > 1
      solver.waveCount should be < solver.size / 2 // many points really move ahead of their list place
    }
  }

  test("after a body leaves the world, the solver still gives the bits of list order") {
    def thinned(): (Seq[Body], IndexedSeq[Collision]) =
      val (world, balls) = BallStack.withBalls(60)
      for _ <- 1 to 30 do world.step()
      world -= balls(7) // the bodies after it get new keys
      for _ <- 1 to 30 do world.step()
      world.detector.detect()
      (world.bodies.toSeq, world.detector.collisions.toIndexedSeq)
    solvesLikeListOrder(thinned(), thinned()) { solver => solver.waveCount should be > 1 }
  }

  test("a fixed body with a velocity of -0.0 keeps the list order (an impulse could make it +0.0)") {
    val (bodies, collisions) = pile()
    val solver = ContactSolver()
    solver.load(collisions)
    solver.waveCount should be > 0
    bodies.filter(_.fixed).foreach(_.linearVelocity = Vector2D(-0.0, 0))
    solver.load(collisions)
    solver.waveCount shouldBe 0
  }

  test("the two shapes of one body order their points as one body") {
    // Collisions b-c, c-right, left-d: the third touches the dumbbell's other shape, so it
    // must wait for the second; keyed per shape it would run first.
    def scene(): (Seq[Body], IndexedSeq[Collision]) =
      val left = Circle(0.5, 1); left.pos = Vector2D(-1, 0)
      val right = Circle(0.5, 1); right.pos = Vector2D(1, 0)
      val b = Circle(0.5, 1); b.pos = Vector2D(2.6, 1.5)
      val c = Circle(0.5, 1); c.pos = Vector2D(1.8, 0.6)
      val d = Circle(0.5, 1); d.pos = Vector2D(-1.9, 0.3)
      val bodies = Seq(Body(left, right), b.asBody, c.asBody, d.asBody)
      val world = sims.dynamics.World()
      for (body, i) <- bodies.zipWithIndex do
        world += body
        body.linearVelocity = Vector2D(0.7 - 0.5 * i, 0.4 * i - 0.9)
        body.angularVelocity = 1.5 - i
      (bodies, IndexedSeq(CircleCollision(b, c), CircleCollision(c, right), CircleCollision(left, d)))
    solvesLikeListOrder(scene(), scene()) { solver => solver.waveCount shouldBe 3 }
  }
