package sims.dynamics

import sims.geometry.{PortableMath, Vector2D}

/** A regular polygon of `n` (at least 3) vertices on a circle of `radius` (the circumradius,
  * m) and a density (kg/m^2). Vertex i is `(0, radius)` rotated by `2 pi i / n`.
  */
final class RegularPolygon(val n: Int, val radius: Double, val density: Double = sims.Defaults.Density)
    extends Polygon(RegularPolygon.corners(n, radius)):
  Shape.requirePositive("density", density)

  /** Area n R^2 sin(2 pi / n) / 2. */
  val volume: Double = n * radius * radius * PortableMath.sin(2 * math.Pi / n) / 2

  /** m R^2 (1 + 2 cos^2(pi / n)) / 6 (the original's formula was wrong; see the deviations). */
  val I: Double =
    val c = PortableMath.cos(math.Pi / n)
    mass * radius * radius * (1 + 2 * c * c) / 6

  Shape.checkDerived(this, s"RegularPolygon(n = $n, radius = $radius, density = $density)")

  override def toString: String = s"RegularPolygon(n = $n, radius = $radius, density = $density, pos = $pos)"

/** Vertex construction of [[RegularPolygon]]. */
object RegularPolygon:
  private[dynamics] def corners(n: Int, radius: Double): IndexedSeq[Vector2D] =
    if n < 3 then throw IllegalArgumentException(s"n must be at least 3, got $n")
    Shape.requirePositive("radius", radius)
    IndexedSeq.tabulate(n)(i => Vector2D(0, radius).rotate(2 * math.Pi * i / n))
