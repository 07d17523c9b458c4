package sims.dynamics

import sims.geometry.{AABB, Projection, Vector2D}

/** A disc of the given radius (m) and density (kg/m^2). */
final class Circle(val radius: Double, val density: Double = sims.Defaults.Density) extends Shape:
  Shape.requirePositive("radius", radius)
  Shape.requirePositive("density", density)

  /** Area pi r^2. */
  val volume: Double = math.Pi * radius * radius

  /** m r^2 / 2. */
  val I: Double = mass * radius * radius / 2

  Shape.checkDerived(this, s"Circle(radius = $radius, density = $density)")

  def AABB: AABB = new sims.geometry.AABB(Vector2D(x - radius, y - radius), Vector2D(x + radius, y + radius))

  /** The interval covered on `axis`: centre projection plus or minus r |axis|. */
  def project(axis: Vector2D): Projection =
    val centre = x * axis.x + y * axis.y
    val extent = radius * axis.length
    Projection(axis, centre - extent, centre + extent)

  def contains(point: Vector2D): Boolean =
    val dx = point.x - x
    val dy = point.y - y
    dx * dx + dy * dy <= radius * radius

  override private[sims] def castRay(x1: Double, y1: Double, dx: Double, dy: Double, maxFraction: Double,
      hit: sims.geometry.RayMath.Hit): Boolean =
    sims.geometry.RayMath.circle(x, y, radius, x1, y1, dx, dy, maxFraction, hit)

  override private[sims] def boundingRadius: Double = radius
  override private[sims] def projectMin(ax: Double, ay: Double): Double = x * ax + y * ay - radius
  override private[sims] def projectMax(ax: Double, ay: Double): Double = x * ax + y * ay + radius
  override private[sims] def minX: Double = x - radius
  override private[sims] def minY: Double = y - radius
  override private[sims] def maxX: Double = x + radius
  override private[sims] def maxY: Double = y + radius

  override def toString: String = s"Circle(radius = $radius, density = $density, pos = $pos)"
