package sims.dynamics

import sims.geometry.Vector2D

/** A rectangle with half extents `halfWidth`, `halfHeight` (m) and a density (kg/m^2).
  * Vertices go counter-clockwise, starting at the upper-right one (at rotation 0).
  */
final class Rectangle(val halfWidth: Double, val halfHeight: Double, val density: Double = sims.Defaults.Density)
    extends Polygon(Rectangle.corners(halfWidth, halfHeight)):
  Shape.requirePositive("density", density)

  /** Area 4 hw hh. */
  val volume: Double = 4 * halfWidth * halfHeight

  /** m ((2 hw)^2 + (2 hh)^2) / 12. */
  val I: Double = mass * ((2 * halfWidth) * (2 * halfWidth) + (2 * halfHeight) * (2 * halfHeight)) / 12

  Shape.checkDerived(this, s"Rectangle(halfWidth = $halfWidth, halfHeight = $halfHeight, density = $density)")

  override def toString: String =
    s"Rectangle(halfWidth = $halfWidth, halfHeight = $halfHeight, density = $density, pos = $pos)"

/** Vertex construction of [[Rectangle]]. */
object Rectangle:
  private[dynamics] def corners(halfWidth: Double, halfHeight: Double): IndexedSeq[Vector2D] =
    Shape.requirePositive("halfWidth", halfWidth)
    Shape.requirePositive("halfHeight", halfHeight)
    IndexedSeq(Vector2D(halfWidth, halfHeight), Vector2D(-halfWidth, halfHeight),
      Vector2D(-halfWidth, -halfHeight), Vector2D(halfWidth, -halfHeight))
