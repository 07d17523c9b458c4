package sims.dynamics

/** A capsule: the points within `radius` (m) of a segment of length 2 `halfLength` (m) along
  * the shape's rotation (the x axis at rotation 0), with a density (kg/m^2): a rectangle of
  * 2 halfLength x 2 radius with a half disc at each end.
  */
final class Capsule(val halfLength: Double, val radius: Double, val density: Double = sims.Defaults.Density) extends RoundedSegment:
  Shape.requirePositive("halfLength", halfLength)
  Shape.requirePositive("radius", radius)
  Shape.requirePositive("density", density)

  /** Area 4 hl r + pi r^2: the rectangle and the two half discs. */
  val volume: Double = 4 * halfLength * radius + math.Pi * radius * radius

  /** The rectangle's m_r ((2 hl)^2 + (2 r)^2) / 12, plus the half discs' (mass m_d together):
    * each about its own centroid, a distance c = 4 r / (3 pi) from its flat side, then moved
    * out to hl + c (parallel axes): m_d (r^2 / 2 + hl^2 + 2 hl c).
    */
  val I: Double =
    val rectangleMass = density * 4 * halfLength * radius
    val discMass = density * math.Pi * radius * radius
    val c = 4 * radius / (3 * math.Pi)
    rectangleMass *
      (4 * halfLength * halfLength + 4 * radius * radius) / 12 +
      discMass *
      (radius * radius / 2 + halfLength * halfLength + 2 * halfLength * c)

  override def toString: String =
    s"Capsule(halfLength = $halfLength, radius = $radius, density = $density, pos = $pos)"
