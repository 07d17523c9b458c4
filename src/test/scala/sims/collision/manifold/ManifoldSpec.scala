package sims.collision.manifold

import java.lang.management.ManagementFactory
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.collision.manifold.ManifoldFixtures.*

/** The manifold record itself: clearing, reuse and its printed form. */
class ManifoldSpec extends AnyFunSuite with Matchers:

  test("a new manifold is empty and has no polygon side") {
    val manifold = Manifold()
    manifold.pointCount shouldBe 0
    manifold.polygonSide shouldBe -1
    manifold.x.length shouldBe Manifold.MaximumPoints
    manifold.id.length shouldBe Manifold.MaximumPoints
  }

  test("clear empties a filled manifold; a refill replaces the old points") {
    val manifold = Manifold()
    PolygonCircleManifold.collide(box(1, 1, 0, 0), circle(0.5, 0, 1.4), -1, SpeculativeDistance, manifold)
    manifold.pointCount shouldBe 1
    manifold.polygonSide shouldBe 0
    manifold.clear()
    manifold.pointCount shouldBe 0
    manifold.polygonSide shouldBe -1
    (manifold.normalX, manifold.normalY) shouldBe (0.0, 0.0)
    PolygonManifold.collide(box(1, 1, 0, 0), box(1, 1, 0, 2), SpeculativeDistance, LinearSlop, manifold)
    manifold.pointCount shouldBe 2
    CircleManifold.collide(circle(1, 0, 0), circle(1, 5, 0), SpeculativeDistance, manifold)
    manifold.pointCount shouldBe 0 // apart: nothing left of the boxes' points
  }

  test("toString shows the normal, each point with its separation and id, and the polygon side") {
    val manifold = Manifold()
    CircleManifold.collide(circle(1, 0, 0), circle(1, 1.5, 0), SpeculativeDistance, manifold)
    manifold.toString shouldBe "Manifold(normal = (1.0, 0.0), points = [(0.75, 0.0) separation -0.5 id 0])"
    PolygonCircleManifold.collide(box(1, 1, 0, 0), circle(0.5, 0, 1.25), -1, SpeculativeDistance, manifold)
    manifold.toString shouldBe
      "Manifold(normal = (0.0, 1.0), points = [(0.0, 0.875) separation -0.25 id 0], polygonSide = 0)"
    manifold.clear()
    manifold.toString shouldBe "Manifold(normal = (0.0, 0.0), points = [])"
  }

  test("colliding allocates nothing per call (measured on library shapes that move between calls)") {
    val threads = ManagementFactory.getThreadMXBean.asInstanceOf[com.sun.management.ThreadMXBean]
    val manifold = Manifold()
    val floor = box(2, 0.5, 0, 0)
    val block = box(0.5, 0.5, 0, 0)
    val ball = circle(0.3, 0, 0)
    val other = circle(0.2, 0, 0)
    val pill = capsule(0.5, 0.2, 0, 0)
    val ground = edge(-3, 0.5, 3, 0.5)
    var sum = 0.0 // read, so that no call can be dropped
    def collideAll(times: Int): Unit =
      var i = 0
      while i < times do
        val shift = (i % 100) * 0.003 // overlapping, touching, speculative, apart, corner to corner
        block.place(0.2 + 3 * shift, 0.97 + shift, (i % 7) * 0.05)
        ball.place(1.5 + shift, 0.3 + 2 * shift, 0)
        other.place(1.5, 0.85 + shift, 0)
        PolygonManifold.collide(floor, block, SpeculativeDistance, LinearSlop, manifold)
        sum += manifold.pointCount
        PolygonCircleManifold.collide(floor, ball, manifold.polygonSide, SpeculativeDistance, manifold)
        sum += manifold.pointCount
        PolygonCircleManifold.collide(ball, block, -1, SpeculativeDistance, manifold)
        sum += manifold.pointCount
        CircleManifold.collide(ball, other, SpeculativeDistance, manifold)
        sum += manifold.pointCount
        pill.place(-1 + shift, 0.69 + shift, (i % 5) * 0.02) // on the edge and the floor, parallel or not
        CapsuleManifold.collide(ground, pill, SpeculativeDistance, LinearSlop, manifold)
        sum += manifold.pointCount
        CapsuleCircleManifold.collide(pill, ball, SpeculativeDistance, manifold)
        sum += manifold.pointCount
        PolygonManifold.collide(floor, pill, SpeculativeDistance, LinearSlop, manifold)
        sum += manifold.pointCount
        i += 1
    collideAll(50000) // warm up: let the JIT compile every path
    val before = threads.getCurrentThreadAllocatedBytes
    collideAll(100000)
    val allocated = threads.getCurrentThreadAllocatedBytes - before
    sum should be > 0.0
    allocated should be < 10000L // 700 000 calls: not one byte per call
  }
