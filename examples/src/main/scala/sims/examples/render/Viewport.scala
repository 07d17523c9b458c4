package sims.examples.render

import sims.scenes.Region
import sims.geometry.Vector2D

/** The world-to-pixel transform of a picture `width` x `height` pixels: world point `centre`
  * is drawn at the picture's middle, one metre is `scale` pixels, and y points up in the
  * world but down on the screen.
  */
final case class Viewport(centre: Vector2D, scale: Double, width: Int, height: Int):
  require(scale > 0 && width > 0 && height > 0, s"invalid viewport: scale $scale, size $width x $height")

  /** Pixel column of world x. */
  def pixelX(x: Double): Double = width / 2.0 + (x - centre.x) * scale

  /** Pixel row of world y. */
  def pixelY(y: Double): Double = height / 2.0 - (y - centre.y) * scale

  /** The world point drawn at pixel (px, py). */
  def toWorld(px: Double, py: Double): Vector2D =
    Vector2D(centre.x + (px - width / 2.0) / scale, centre.y - (py - height / 2.0) / scale)

  /** The part of the world this viewport shows. */
  def visible: Region =
    val lowerLeft = toWorld(0, height)
    val upperRight = toWorld(width, 0)
    Region(lowerLeft.x, lowerLeft.y, upperRight.x, upperRight.y)

  /** The same view zoomed by `factor` (above 1 magnifies) keeping the world point under
    * pixel (px, py) in place.
    */
  def zoomed(factor: Double, px: Double, py: Double): Viewport =
    val fixedPoint = toWorld(px, py)
    val newScale = scale * factor
    val newCentre = Vector2D(fixedPoint.x - (px - width / 2.0) / newScale, fixedPoint.y + (py - height / 2.0) / newScale)
    copy(centre = newCentre, scale = newScale)

  /** The same view moved so the picture shifts by (dx, dy) pixels. */
  def panned(dx: Double, dy: Double): Viewport = copy(centre = Vector2D(centre.x - dx / scale, centre.y + dy / scale))

  /** The same view in a picture of another size, keeping centre and scale. */
  def resized(newWidth: Int, newHeight: Int): Viewport = copy(width = newWidth, height = newHeight)

/** Construction of viewports. */
object Viewport:
  /** The largest-scale viewport of a `width` x `height` picture showing all of `region`
    * (centred, so one direction may show more than the region).
    */
  def fit(region: Region, width: Int, height: Int): Viewport =
    val scale = math.min(width / region.width, height / region.height)
    Viewport(region.centre, scale, width, height)
