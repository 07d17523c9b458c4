package sims.collision.manifold

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.collision.manifold.ManifoldFixtures.*
import sims.dynamics.{RoundedSegment, Shape}
import sims.geometry.Vector2D

/** The laws every manifold function keeps, as property tests for one function: moving the
  * pair rigidly moves the manifold with it; points lie midway between the outlines; apart pairs
  * have no point nearer than their gap and none beyond the speculative distance; overlapping
  * pairs have a point of separation at most 0.
  */
trait ManifoldLaws extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  /** Checks normal and points of `manifold` (points in order) against the expected values, to 1e-12. */
  protected def shouldHave(manifold: Manifold, normal: Vector2D, expected: Point*): Unit =
    manifold.pointCount shouldBe expected.length
    manifold.normalX shouldBe normal.x +- 1e-12
    manifold.normalY shouldBe normal.y +- 1e-12
    for (point, wanted) <- points(manifold).zip(expected) do
      point.x shouldBe wanted.x +- 1e-12
      point.y shouldBe wanted.y +- 1e-12
      point.separation shouldBe wanted.separation +- 1e-12
      point.id shouldBe wanted.id

  /** Registers the law tests for pairs from `pairs` collided by `collide`, named after `pairsName`.
    * `outlineSlack` widens the midway law where a manifold places points along its normal while
    * a rounded outline is tilted to it (see [[tiltSlack]]).
    */
  protected def manifoldLaws[A <: Shape, B <: Shape](pairsName: String, pairs: Gen[(A, B)],
      collide: (A, B) => Manifold, outlineSlack: (A, B, Manifold) => Double = (_: A, _: B, _: Manifold) => 0.0): Unit =
    test(s"law ($pairsName): moving the pair rigidly moves the points with it and keeps separations and ids") {
      forAll(pairs, Gen.choose(-math.Pi, math.Pi), position, minSuccessful(300)) { case ((a, b), angle, shift) =>
        val before = collide(a, b)
        val expected = points(before)
        val normal = Vector2D(before.normalX, before.normalY).rotate(angle)
        moveRigidly(a, angle, shift.x, shift.y)
        moveRigidly(b, angle, shift.x, shift.y)
        val after = collide(a, b)
        after.pointCount shouldBe before.pointCount
        for (moved, p) <- points(after).zip(expected) do
          val point = Vector2D(p.x, p.y).rotate(angle) + shift
          moved.x shouldBe point.x +- 1e-9
          moved.y shouldBe point.y +- 1e-9
          moved.separation shouldBe p.separation +- 1e-9
          moved.id shouldBe p.id
        if after.pointCount > 0 then
          after.normalX shouldBe normal.x +- 1e-9
          after.normalY shouldBe normal.y +- 1e-9
      }
    }

    test(s"law ($pairsName): each point lies within |s| / 2 of both outlines, with s at most the speculative distance") {
      forAll(pairs, minSuccessful(500)) { case (a, b) =>
        val manifold = collide(a, b)
        for p <- points(manifold) do
          val half = math.abs(p.separation) / 2 + 1e-9 + outlineSlack(a, b, manifold)
          outlineDistance(a, p.x, p.y) should be <= half
          outlineDistance(b, p.x, p.y) should be <= half
          p.separation should be <= SpeculativeDistance
        if manifold.pointCount > 0 then math.hypot(manifold.normalX, manifold.normalY) shouldBe 1.0 +- 1e-12
        if manifold.pointCount == 2 then manifold.id(0) should not be manifold.id(1)
      }
    }

    test(s"law ($pairsName): apart, no point nearer than the gap nor beyond the speculative distance; overlapping, one at most 0") {
      forAll(pairs, minSuccessful(500)) { case (a, b) =>
        val manifold = collide(a, b)
        val separations = points(manifold).map(_.separation)
        val gap = distance(a, b)
        if gap > SpeculativeDistance then manifold.pointCount shouldBe 0
        else if gap > 0 then
          separations should not be empty
          for s <- separations do s should be >= gap - 1e-9
        else
          separations should not be empty
          separations.min should be <= 1e-12
      }
    }

  /** A manifold's points lie along its normal n from a core point q, at q - n r on a rounded
    * outline of radius r around it. Where that core is tilted to the normal's perpendicular
    * (the sine of the tilt is n . u, u along the core), the outline passes through that point
    * within r (1 - cos) of the tilt: the slack of the midway law for such a shape.
    */
  protected def tiltSlack(shape: RoundedSegment, manifold: Manifold): Double =
    val u = (shape.vertex2 - shape.vertex1).unit
    val sine = math.min(1.0, math.abs(u.x * manifold.normalX + u.y * manifold.normalY))
    shape.radius * (1 - math.sqrt(1 - sine * sine))
