package sims.geometry

/** An immutable two-dimensional vector of doubles, the basic quantity of SiMS (positions,
  * velocities, forces, impulses). Angular quantities are plain `Double`s: the z component of
  * the 3D pseudovector.
  */
final case class Vector2D(x: Double, y: Double):

  /** Vector sum. */
  inline def +(v: Vector2D): Vector2D = Vector2D(x + v.x, y + v.y)

  /** Vector difference. */
  inline def -(v: Vector2D): Vector2D = Vector2D(x - v.x, y - v.y)

  /** This vector scaled by `n`. */
  inline def *(n: Double): Vector2D = Vector2D(x * n, y * n)

  /** This vector divided by `n`. */
  inline def /(n: Double): Vector2D = Vector2D(x / n, y / n)

  /** The opposite vector. */
  inline def unary_- : Vector2D = Vector2D(-x, -y)

  /** Dot product. */
  inline def dot(v: Vector2D): Double = x * v.x + y * v.y

  /** The z component of the 3D cross product: `x * v.y - y * v.x`. */
  inline def cross(v: Vector2D): Double = x * v.y - y * v.x

  /** Euclidean length; finite for every finite vector (no overflow of x^2 + y^2 for huge
    * components, no underflow to 0 for tiny ones).
    */
  def length: Double =
    val squared = x * x + y * y
    if Vector2D.safeSquare(squared) then math.sqrt(squared) else Vector2D.scaledLength(x, y)

  /** The unit vector of this direction; fails on the null vector, which has no direction, and
    * on a non-finite vector.
    */
  def unit: Vector2D =
    val squared = x * x + y * y
    if Vector2D.safeSquare(squared) then
      val l = math.sqrt(squared)
      Vector2D(x / l, y / l)
    else
      if !isFinite then throw IllegalArgumentException(s"Vector2D.unit: $this is not finite")
      if x == 0 && y == 0 then throw IllegalArgumentException("Vector2D.unit: the null vector has no unit vector")
      // Scaled by the larger component first: both quotients are at most 1 and one is exactly 1.
      val scale = math.max(math.abs(x), math.abs(y))
      val sx = x / scale
      val sy = y / scale
      val l = math.sqrt(sx * sx + sy * sy)
      Vector2D(sx / l, sy / l)

  /** The vector projection of this vector onto `v`; the null vector when `v` is null. */
  def project(v: Vector2D): Vector2D =
    val vv = v dot v
    if vv == 0 then Vector2D.Null else v * ((this dot v) / vv)

  /** This vector rotated counter-clockwise by `angle` radians. */
  def rotate(angle: Double): Vector2D =
    val c = PortableMath.cos(angle)
    val s = PortableMath.sin(angle)
    Vector2D(x * c - y * s, x * s + y * c)

  /** The left normal `(-y, x)`, this vector rotated by +90 degrees. */
  inline def leftNormal: Vector2D = Vector2D(-y, x)

  /** The right normal `(y, -x)`, this vector rotated by -90 degrees. */
  inline def rightNormal: Vector2D = Vector2D(y, -x)

  /** True for the null vector (both components exactly zero). */
  def isNull: Boolean = x == 0 && y == 0

  /** The components as a list `List(x, y)`. */
  def components: List[Double] = List(x, y)

  /** True when both components are finite (neither NaN nor infinite). */
  def isFinite: Boolean = !x.isNaN && !y.isNaN && !x.isInfinite && !y.isInfinite

  override def toString: String = s"($x, $y)"

/** Constants of [[Vector2D]]. */
object Vector2D:
  /** The null vector (0, 0). */
  val Null: Vector2D = Vector2D(0, 0)

  /** The zero vector (0, 0): the same as `Null`, by the name other libraries use. */
  val Zero: Vector2D = Null

  /** `n * v`: the vector `v` scaled by `n`, the same as `v * n`. */
  extension (n: Double) inline def *(v: Vector2D): Vector2D = Vector2D(n * v.x, n * v.y)

  /** The unit vector along x, (1, 0). */
  val i: Vector2D = Vector2D(1, 0)

  /** The unit vector along y, (0, 1). */
  val j: Vector2D = Vector2D(0, 1)

  // x^2 + y^2 between these needs no rescaling: sqrt of it is exact to rounding (and gives the
  // same bits as always). Outside, a component's square overflowed or lost precision.
  private val SmallestSafeSquare = java.lang.Double.MIN_NORMAL * (1L << 53).toDouble
  private val LargestSafeSquare = Double.MaxValue

  private[sims] inline def safeSquare(squared: Double): Boolean =
    squared >= SmallestSafeSquare && squared <= LargestSafeSquare

  /** The length of (x, y) when x^2 + y^2 over- or underflows: scaled by the larger component. */
  private def scaledLength(x: Double, y: Double): Double =
    val scale = math.max(math.abs(x), math.abs(y))
    if scale == 0 || scale.isInfinite || scale.isNaN then math.sqrt(x * x + y * y)
    else
      val sx = x / scale
      val sy = y / scale
      scale * math.sqrt(sx * sx + sy * sy)

  /** Checks that `value` is finite; otherwise throws an IllegalArgumentException naming `name`. */
  private[sims] def requireFinite(name: String, value: Vector2D): Vector2D =
    if value == null then throw IllegalArgumentException(s"$name must not be null")
    if !value.isFinite then throw IllegalArgumentException(s"$name must be finite, got $value")
    value

  /** Checks that `value` is finite; otherwise throws an IllegalArgumentException naming `name`. */
  private[sims] def requireFinite(name: String, value: Double): Double =
    if !java.lang.Double.isFinite(value) then
      throw IllegalArgumentException(s"$name must be finite, got $value")
    value
