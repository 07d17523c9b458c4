package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.Defaults
import sims.dynamics.{Body, Capsule, Circle, Rectangle, RegularPolygon, Shape}
import sims.geometry.Vector2D

/** TimeOfImpact: the first fraction of a body's motion at which its shape reaches the target
  * depth in a fixed shape, never passing it, whatever the motion.
  */
class TimeOfImpactSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:
  private val depth = Defaults.BulletDepth

  /** A body of one shape at (x, y), turned by `angle`. */
  private def body(shape: Shape, x: Double, y: Double, angle: Double = 0): Body =
    val b = shape.asBody
    b.pos = Vector2D(x, y)
    b.rotation = angle
    b

  private def wall(): Rectangle =
    val wall = Rectangle(0.025, 1, 1)
    wall.asBody.fixed = true
    wall

  test("a ball flying straight at a thin wall meets it where it reaches the depth") {
    val ball = Circle(0.1, 1)
    val b = body(ball, -3, 0.3)
    val t = TimeOfImpact().fraction(b, -3, 0.3, 0, 5, 0, 0, ball, wall(), depth, 1)
    // The ball's front at x = -0.025 + depth: its centre at -0.125 + depth.
    val expected = (-0.125 + depth + 3) / 5
    t shouldBe expected +- Defaults.BulletTolerance / 5
    t should be <= expected
  }

  test("a motion away from, along, or short of the wall, or starting against it, does not meet it") {
    val impact = TimeOfImpact()
    val ball = Circle(0.1, 1)
    val b = body(ball, -1, 0)
    impact.fraction(b, -1, 0, 0, -5, 0, 0, ball, wall(), depth, 1) shouldBe 1.0 // away
    impact.fraction(b, -1, 0, 0, 0, 5, 0, ball, wall(), depth, 1) shouldBe 1.0 // along
    impact.fraction(b, -1, 0, 0, 0.5, 0, 0, ball, wall(), depth, 1) shouldBe 1.0 // short of it
    impact.fraction(b, -0.12, 0, 0, 5, 0, 0, ball, wall(), depth, 1) shouldBe 1.0 // touching at the start
    impact.fraction(b, -1, 0, 0, 5, 0, 0, ball, wall(), depth, 0.1) shouldBe 0.1 // not before the limit
  }

  test("a rolling ball's own turning does not count; a turning box's corners do") {
    val impact = TimeOfImpact()
    val ball = Circle(0.1, 1)
    val b = body(ball, -1, 0)
    // Approaching slowly and spinning fast: a circle's turning moves no point of its outline.
    impact.fraction(b, -1, 0, 0, 0.8, 0, 200, ball, wall(), depth, 1) shouldBe 1.0
    val stick = Rectangle(0.5, 0.01, 1)
    val s = body(stick, -0.4, 0, math.Pi / 2)
    // Upright 0.4 m from the wall, not moving, turning a quarter: its end sweeps into the wall
    // when it is 0.707 rad from lying flat (0.4 - 0.5 cos a = 0.025).
    val t = impact.fraction(s, -0.4, 0, math.Pi / 2, 0, 0, -math.Pi / 2, stick, wall(), depth, 1)
    t shouldBe (1 - math.acos(0.375 / 0.5) / (math.Pi / 2)) +- 0.03
  }

  private val shapes: Gen[Shape] = Gen.oneOf(
    Gen.choose(0.02, 0.3).map(r => Circle(r, 1)),
    for hw <- Gen.choose(0.02, 0.5); hh <- Gen.choose(0.01, 0.3) yield Rectangle(hw, hh, 1),
    for n <- Gen.choose(3, 7); r <- Gen.choose(0.03, 0.3) yield RegularPolygon(n, r, 1),
    for l <- Gen.choose(0.02, 0.4); r <- Gen.choose(0.01, 0.2) yield Capsule(l, r, 1))

  test("property: the fraction found is where the depth is first reached; before it the shapes never reach it") {
    val impact = TimeOfImpact()
    val separation = ShapeSeparation()
    var searches, short = 0
    forAll(shapes, Gen.choose(-1.0, 1.0), Gen.choose(-1.0, 1.0), Gen.choose(1.0, 8.0), Gen.choose(-2.0, 2.0),
      Gen.choose(-12.0, 12.0), minSuccessful(1000)) { (shape, y0, angle0, dx, dy, dAngle) =>
      val fixed = wall()
      val b = body(shape, -1.5, y0, angle0)
      val x0 = b.pos.x
      separation.measure(fixed, shape) shouldBe true
      whenever(separation.distance > Defaults.ContactHysteresis) {
        val t = impact.fraction(b, x0, y0, angle0, dx, dy, dAngle, shape, fixed, depth, 1)
        def at(f: Double): Double =
          b.pos = Vector2D(x0 + f * dx, y0 + f * dy)
          b.rotation = angle0 + f * dAngle
          separation.measure(fixed, shape)
          separation.distance
        // Sampled finely, the path before t never reaches the depth.
        val samples = 400
        for k <- 0 until samples do
          val f = t * k / samples
          at(f) should be > -depth - 1e-9
        searches += 1
        if impact.stoppedShort then short += 1
        else if t < 1 then at(t) should (be <= -depth + Defaults.BulletTolerance + 1e-9 and be > -depth - 1e-9)
        else for k <- 0 to samples do at(k.toDouble / samples) should be > -depth - 1e-9
      }
    }
    info(s"$short of $searches searches stopped short (fast turns grazing a corner)")
    short.toDouble should be <= 0.02 * searches
  }
