package sims.geometry

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

class GeometrySpec extends AnyFunSuite with Matchers:

  test("segment direction, normals and length") {
    val s = Segment(Vector2D(1, 1), Vector2D(4, 5))
    s.d shouldBe Vector2D(3, 4)
    s.d0 shouldBe Vector2D(0.6, 0.8)
    s.n shouldBe Vector2D(4, -3)
    s.n0 shouldBe Vector2D(0.8, -0.6)
    s.length shouldBe 5.0
  }

  test("segment distance: to the interior, to each end, on the segment") {
    val s = Segment(Vector2D(0, 0), Vector2D(2, 0))
    s.distance(Vector2D(1, 3)) shouldBe 3.0
    s.distance(Vector2D(-3, 4)) shouldBe 5.0
    s.distance(Vector2D(5, -4)) shouldBe 5.0
    s.distance(Vector2D(1.5, 0)) shouldBe 0.0
    Segment(Vector2D(1, 1), Vector2D(1, 1)).distance(Vector2D(4, 5)) shouldBe 5.0
  }

  test("ray intersects segments in front of it only") {
    val ray = Ray(Vector2D(0, 0), Vector2D(1, 0))
    ray.intersects(Segment(Vector2D(2, -1), Vector2D(2, 1))) shouldBe true
    ray.intersects(Segment(Vector2D(-2, -1), Vector2D(-2, 1))) shouldBe false
    ray.intersects(Segment(Vector2D(2, 0.5), Vector2D(2, 1))) shouldBe false
    ray.intersects(Segment(Vector2D(2, 0), Vector2D(3, 0))) shouldBe true // collinear ahead
    ray.intersects(Segment(Vector2D(-3, 0), Vector2D(-2, 0))) shouldBe false // collinear behind
    ray.intersects(Segment(Vector2D(2, 1), Vector2D(3, 1))) shouldBe false // parallel
    ray.contains(Vector2D(5, 0)) shouldBe true
    ray.contains(Vector2D(-5, 0)) shouldBe false
    ray.contains(Vector2D(5, 1)) shouldBe false
    intercept[IllegalArgumentException](Ray(Vector2D.Null, Vector2D.Null))
  }

  test("projection overlap") {
    val a = Projection(Vector2D.i, 0, 2)
    a.overlaps(Projection(Vector2D.i, 1, 3)) shouldBe true
    a.overlap(Projection(Vector2D.i, 1, 3)) shouldBe 1.0
    a.overlaps(Projection(Vector2D.i, 2, 3)) shouldBe true // touching
    a.overlap(Projection(Vector2D.i, 2, 3)) shouldBe 0.0
    a.overlaps(Projection(Vector2D.i, 2.5, 3)) shouldBe false
    a.overlap(Projection(Vector2D.i, 2.5, 3)) shouldBe 0.0
    a.overlap(Projection(Vector2D.i, 0.5, 1)) shouldBe 0.5 // contained
  }

  test("AABB overlap, touching counts") {
    val a = AABB(Vector2D(0, 0), Vector2D(1, 1))
    a.overlaps(AABB(Vector2D(0.5, 0.5), Vector2D(2, 2))) shouldBe true
    a.overlaps(AABB(Vector2D(1, 0), Vector2D(2, 1))) shouldBe true
    a.overlaps(AABB(Vector2D(1.1, 0), Vector2D(2, 1))) shouldBe false
    a.overlaps(AABB(Vector2D(0, -2), Vector2D(1, -0.1))) shouldBe false
  }

  test("matrix solve and singular matrices") {
    val m = Matrix22(2, 1, 1, 3)
    val x = m.solve(Vector2D(3, 5))
    (m * x).x shouldBe 3.0 +- 1e-12
    (m * x).y shouldBe 5.0 +- 1e-12
    m.determinant shouldBe 5.0
    (m + Matrix22.Identity) shouldBe Matrix22(3, 1, 1, 4)
    Matrix22(1, 2, 2, 4).solve(Vector2D(1, 1)) shouldBe Vector2D.Null
  }

  /** A counter-clockwise triangle as a plain ConvexPolygon, to test the trait's defaults. */
  private object Triangle extends ConvexPolygon:
    val vertices = IndexedSeq(Vector2D(0, 0), Vector2D(2, 0), Vector2D(0, 2))

  test("convex polygon defaults: sides, projection, AABB, containment") {
    Triangle.sides.map(_.n0) shouldBe IndexedSeq(Vector2D(0, -1), Vector2D(1, 1).unit, Vector2D(-1, 0))
    Triangle.project(Vector2D(1, 1)) shouldBe Projection(Vector2D(1, 1), 0, 2)
    Triangle.AABB shouldBe AABB(Vector2D(0, 0), Vector2D(2, 2))
    Triangle.contains(Vector2D(0.5, 0.5)) shouldBe true
    Triangle.contains(Vector2D(1, 1)) shouldBe true // on the hypotenuse
    Triangle.contains(Vector2D(1.5, 1.5)) shouldBe false
    Triangle.vertexCount shouldBe 3
    Triangle.vertexXs(1) shouldBe 2.0
    Triangle.vertexYs(2) shouldBe 2.0
  }
