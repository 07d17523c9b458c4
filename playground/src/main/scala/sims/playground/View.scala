package sims.playground

import sims.geometry.Vector2D
import sims.scenes.Region

/** What part of the world the canvas shows: the world point at the canvas's centre and the
  * scale in pixels per metre (y grows upwards in the world, downwards on the canvas).
  */
final case class View(centre: Vector2D, scale: Double, width: Double, height: Double):
  /** The canvas x of world x. */
  def pixelX(x: Double): Double = width / 2 + (x - centre.x) * scale

  /** The canvas y of world y. */
  def pixelY(y: Double): Double = height / 2 - (y - centre.y) * scale

  /** The world point at canvas pixel (px, py). */
  def toWorld(px: Double, py: Double): Vector2D =
    Vector2D(centre.x + (px - width / 2) / scale, centre.y - (py - height / 2) / scale)

  /** Moved by (dx, dy) pixels: what was under the pointer stays under it. */
  def panned(dx: Double, dy: Double): View = copy(centre = Vector2D(centre.x - dx / scale, centre.y + dy / scale))

  /** Zoomed by `factor` about canvas pixel (px, py), which keeps showing the same world point. */
  def zoomed(factor: Double, px: Double, py: Double): View =
    val fixed = toWorld(px, py)
    val newScale = math.min(View.MaxScale, math.max(View.MinScale, scale * factor))
    copy(centre = Vector2D(fixed.x - (px - width / 2) / newScale, fixed.y + (py - height / 2) / newScale),
      scale = newScale)

object View:
  /** Zoom limits, pixels per metre. */
  val MinScale: Double = 0.5
  val MaxScale: Double = 2000.0

  /** The view that shows all of `region` on a canvas of this size, with a small margin. */
  def fit(region: Region, width: Double, height: Double): View =
    val scale = 0.95 * math.min(width / region.width, height / region.height)
    View(region.centre, scale, width, height)
