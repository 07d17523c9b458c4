package sims.geometry

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** Ray casts against each outline, hand-computed. */
class RayMathSpec extends AnyFunSuite with Matchers:

  /** The hit (fraction, normal x, normal y) of a cast, or None. */
  private def cast(f: RayMath.Hit => Boolean): Option[(Double, Double, Double)] =
    val hit = RayMath.Hit()
    if f(hit) then Some((hit.fraction, hit.normalX, hit.normalY)) else None

  test("circle: enters where the ray first meets it; a start inside or a short ray misses") {
    // Unit circle at (3, 0), ray from the origin to (10, 0): enters at x = 2, fraction 0.2.
    cast(RayMath.circle(3, 0, 1, 0, 0, 10, 0, 1, _)) shouldBe Some((0.2, -1.0, 0.0))
    cast(RayMath.circle(3, 0, 1, 0, 0, 10, 0, 0.19, _)) shouldBe None // stops short
    cast(RayMath.circle(3, 0, 1, 3, 0, 10, 0, 1, _)) shouldBe None // starts inside
    cast(RayMath.circle(3, 0, 1, 0, 1, 10, 0, 1, _)) shouldBe Some((0.3, 0.0, 1.0)) // grazes the top
    cast(RayMath.circle(3, 0, 1, 0, 1.01, 10, 0, 1, _)) shouldBe None
    cast(RayMath.circle(3, 0, 1, 0, 0, 0, 0, 1, _)) shouldBe None // no length
  }

  // A 2 x 2 box about the origin, counter-clockwise from the upper right, with its normals.
  private val xs = Array(1.0, -1.0, -1.0, 1.0)
  private val ys = Array(1.0, 1.0, -1.0, -1.0)
  private val normalXs = Array(0.0, -1.0, 0.0, 1.0)
  private val normalYs = Array(1.0, 0.0, -1.0, 0.0)
  private def box(x1: Double, y1: Double, dx: Double, dy: Double, maxFraction: Double = 1) =
    cast(RayMath.polygon(xs, ys, normalXs, normalYs, 4, x1, y1, dx, dy, maxFraction, _))

  test("polygon: the side it comes in through; parallel outside, a start inside and a short ray miss") {
    box(-5, 0.5, 10, 0) shouldBe Some((0.4, -1.0, 0.0))
    box(0.5, 5, 0, -10) shouldBe Some((0.4, 0.0, 1.0))
    box(-3, -3, 4, 4) shouldBe Some((0.5, 0.0, -1.0)) // through the corner: the later side of the tie
    box(-5, 2, 10, 0) shouldBe None // parallel, above
    box(0, 0, 10, 0) shouldBe None // starts inside
    box(-5, 0.5, 10, 0, 0.3) shouldBe None
    box(-5, 0.5, -10, 0) shouldBe None // points away
  }

  test("segment: hit from either side, the normal facing the start; along its line it is missed") {
    cast(RayMath.segment(0, -1, 0, 1, -2, 0, 4, 0, 1, _)) shouldBe Some((0.5, -1.0, 0.0))
    cast(RayMath.segment(0, -1, 0, 1, 2, 0, -4, 0, 1, _)) shouldBe Some((0.5, 1.0, 0.0))
    cast(RayMath.segment(0, -1, 0, 1, -2, 1.5, 4, 0, 1, _)) shouldBe None // passes beyond an end
    cast(RayMath.segment(0, -1, 0, 1, 0, -3, 0, 6, 1, _)) shouldBe None // along the line
  }

  test("capsule: its sides, its round ends; a start inside misses") {
    // Core from (-1, 0) to (1, 0), radius 0.5.
    def capsule(x1: Double, y1: Double, dx: Double, dy: Double) =
      cast(RayMath.capsule(-1, 0, 1, 0, 0.5, x1, y1, dx, dy, 1, _))
    capsule(0.5, 3, 0, -4) shouldBe Some((0.625, 0.0, 1.0)) // the upper side, at y = 0.5
    capsule(0.5, -3, 0, 4) shouldBe Some((0.625, 0.0, -1.0))
    capsule(4, 0, -4, 0) shouldBe Some((0.625, 1.0, 0.0)) // the right end's tip, at x = 1.5
    val Some((fraction, nx, ny)) = capsule(4, 0.3, -4, 0): @unchecked // the round end, off its tip
    fraction shouldBe (4 - (1 + 0.4)) / 4 +- 1e-12
    nx shouldBe 0.8 +- 1e-12
    ny shouldBe 0.6 +- 1e-12
    capsule(0, 0.2, 4, 0) shouldBe None // starts inside
    cast(RayMath.capsule(-1, 0, 1, 0, 0, 0.5, 3, 0, -4, 1, _)) shouldBe Some((0.75, 0.0, 1.0)) // radius 0: the segment
  }

  test("a ray 2e8 m long across a 0.24 m circle or capsule at the origin: the hit on the outline, a unit normal, exactly when it crosses") {
    for offset <- Seq(0.0, 0.1, -0.2, 0.239, 0.2399999, 0.2400001, 0.25, -0.3) do
      val crosses = math.abs(offset) < 0.24
      val onCircle = cast(RayMath.circle(0, 0, 0.24, -1e8, offset, 2e8, 0, 1, _))
      val onCapsule = cast(RayMath.capsule(-0.5, 0, 0.5, 0, 0.24, -1e8, offset, 2e8, 0, 1, _))
      withClue(s"offset $offset: ") {
        onCircle.isDefined shouldBe crosses
        onCapsule.isDefined shouldBe crosses
        for (t, nx, ny) <- onCircle do
          val (x, y) = (-1e8 + t * 2e8, offset)
          math.hypot(nx, ny) shouldBe 1.0 +- 1e-12
          math.hypot(x, y) shouldBe 0.24 +- 1e-7 // on the circle, to the ray's own resolution there
          nx should be < 0.0
        for (t, nx, ny) <- onCapsule do
          math.hypot(nx, ny) shouldBe 1.0 +- 1e-12
          (-1e8 + t * 2e8) shouldBe (-0.5 - math.sqrt(0.24 * 0.24 - offset * offset)) +- 1e-7
      }
  }
