package sims.examples.render

import org.scalatest.funsuite.AnyFunSuite
import sims.scenes.Region
import sims.geometry.Vector2D

/** The world-to-pixel transform. */
class ViewportSpec extends AnyFunSuite:
  private val viewport = Viewport(Vector2D(1, 2), 10, 200, 100)

  test("the centre is drawn at the middle, y points down on screen"):
    assert(viewport.pixelX(1) == 100 && viewport.pixelY(2) == 50)
    assert(viewport.pixelX(2) == 110 && viewport.pixelY(3) == 40)

  test("toWorld inverts the transform"):
    val p = viewport.toWorld(viewport.pixelX(-3.5), viewport.pixelY(7.25))
    assert(math.abs(p.x + 3.5) < 1e-12 && math.abs(p.y - 7.25) < 1e-12)

  test("fit shows the whole region, centred"):
    val fitted = Viewport.fit(Region(-4, -1, 4, 5), 480, 360)
    val visible = fitted.visible
    assert(visible.minX <= -4 && visible.maxX >= 4 && visible.minY <= -1 && visible.maxY >= 5)
    assert(fitted.centre == Vector2D(0, 2))
    assert(fitted.scale == 60) // 360 px for 6 m

  test("zooming keeps the world point under the pointer in place"):
    val before = viewport.toWorld(30, 70)
    val zoomed = viewport.zoomed(2.5, 30, 70)
    val after = zoomed.toWorld(30, 70)
    assert(zoomed.scale == 25)
    assert(math.abs(before.x - after.x) < 1e-12 && math.abs(before.y - after.y) < 1e-12)

  test("panning moves the picture by the given pixels"):
    val panned = viewport.panned(20, -10)
    assert(math.abs(panned.pixelX(1) - 120) < 1e-12 && math.abs(panned.pixelY(2) - 40) < 1e-12)
