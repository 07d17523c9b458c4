package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Rectangle, RegularPolygon, Shape}
import sims.geometry.{ConvexPolygon, Vector2D}

/** The separating axis test against a brute-force overlap test on sampled points. */
class SatSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private type Polygon = Shape & ConvexPolygon

  private val polygons: Gen[Polygon] =
    for
      shape <- Gen.oneOf(
        for hw <- Gen.choose(0.1, 2.0); hh <- Gen.choose(0.1, 2.0) yield Rectangle(hw, hh, 1),
        for n <- Gen.choose(3, 9); r <- Gen.choose(0.1, 2.0) yield RegularPolygon(n, r, 1))
      x <- Gen.choose(-2.0, 2.0)
      y <- Gen.choose(-2.0, 2.0)
      rotation <- Gen.choose(-math.Pi, math.Pi)
    yield
      shape.pos = Vector2D(x, y)
      shape.rotation = rotation
      shape

  /** Whether some sampled point lies in both polygons (spacing `step`). */
  private def sampledOverlap(a: Polygon, b: Polygon, step: Double): Boolean =
    val lo = Vector2D(math.max(a.AABB.minVertex.x, b.AABB.minVertex.x), math.max(a.AABB.minVertex.y, b.AABB.minVertex.y))
    val hi = Vector2D(math.min(a.AABB.maxVertex.x, b.AABB.maxVertex.x), math.min(a.AABB.maxVertex.y, b.AABB.maxVertex.y))
    var x = lo.x
    var found = false
    while !found && x <= hi.x do
      var y = lo.y
      while !found && y <= hi.y do
        val p = Vector2D(x, y)
        found = a.contains(p) && b.contains(p)
        y += step
      x += step
    found

  /** The least overlap over all side normals: how deep the polygons overlap. */
  private def depth(a: Polygon, b: Polygon): Double = (a.sides ++ b.sides).map(_.n0).map(n => a.project(n).overlap(b.project(n))).min

  test("SAT agrees with sampled points on random convex pairs") {
    forAll(polygons, polygons, minSuccessful(300)) { (a, b) =>
      val sat = PolyCollision.colliding(a, b)
      val sampled = sampledOverlap(a, b, 0.01)
      if sampled then sat shouldBe true // a common point means they overlap
      if sat && !sampled then depth(a, b) should be < 0.03 // only thin overlaps escape the samples
      PolyCollision.colliding(b, a) shouldBe sat // symmetric
    }
  }
