package sims.geometry

/** The polygon geometry every part of the library shares, written once, on vertex arrays
  * (world coordinates, counter-clockwise; side i goes from vertex i to vertex i + 1): whether a
  * point is inside, the projection onto an axis, the outward side normals and the side a point
  * lies farthest outside of. Allocation-free,
  * for the narrowphase's loops; the vector API (`ConvexPolygon`) calls the same functions.
  */
private[sims] object PolygonMath:
  /** The vertex after vertex i (the last one's is vertex 0). */
  inline def next(i: Int, count: Int): Int = if i + 1 == count then 0 else i + 1

  /** True if (x, y) lies inside or on the polygon: left of (or on) every side. */
  def contains(xs: Array[Double], ys: Array[Double], count: Int, x: Double, y: Double): Boolean =
    var inside = true
    var i = 0
    while inside && i < count do
      val j = next(i, count)
      if (xs(j) - xs(i)) * (y - ys(i)) - (ys(j) - ys(i)) * (x - xs(i)) < 0 then inside = false
      i += 1
    inside

  /** The lowest projection x_i * ax + y_i * ay of a vertex onto the axis (ax, ay). */
  def projectionMin(xs: Array[Double], ys: Array[Double], count: Int, ax: Double, ay: Double): Double =
    var lower = Double.PositiveInfinity
    var i = 0
    while i < count do
      val p = xs(i) * ax + ys(i) * ay
      if p < lower then lower = p
      i += 1
    lower

  /** The highest projection of a vertex onto the axis (ax, ay). */
  def projectionMax(xs: Array[Double], ys: Array[Double], count: Int, ax: Double, ay: Double): Double =
    var upper = Double.NegativeInfinity
    var i = 0
    while i < count do
      val p = xs(i) * ax + ys(i) * ay
      if p > upper then upper = p
      i += 1
    upper

  /** x of the outward unit normal of side i: the side's right normal (dy, -dx) / |d|. */
  def sideNormalX(xs: Array[Double], ys: Array[Double], count: Int, i: Int): Double =
    val j = next(i, count)
    val dx = xs(j) - xs(i)
    val dy = ys(j) - ys(i)
    dy / math.sqrt(dx * dx + dy * dy)

  /** y of the outward unit normal of side i. */
  def sideNormalY(xs: Array[Double], ys: Array[Double], count: Int, i: Int): Double =
    val j = next(i, count)
    val dx = xs(j) - xs(i)
    val dy = ys(j) - ys(i)
    -dx / math.sqrt(dx * dx + dy * dy)

  /** Fills `normalXs`, `normalYs` with the outward unit normals of all sides. */
  def sideNormals(xs: Array[Double], ys: Array[Double], count: Int, normalXs: Array[Double], normalYs: Array[Double]): Unit =
    var i = 0
    while i < count do
      normalXs(i) = sideNormalX(xs, ys, count, i)
      normalYs(i) = sideNormalY(xs, ys, count, i)
      i += 1

  /** How far (x, y) lies outside the line of side i (negative: inside it), along the side's
    * outward unit normal (normalXs(i), normalYs(i)).
    */
  inline def sideDistance(xs: Array[Double], ys: Array[Double], normalXs: Array[Double], normalYs: Array[Double],
      i: Int, x: Double, y: Double): Double =
    normalXs(i) * (x - xs(i)) + normalYs(i) * (y - ys(i))

  /** The side whose line (x, y) lies farthest outside of (`sideDistance` greatest; the first such
    * side on a tie): for a point inside the polygon, the side it is least deep behind.
    */
  def farthestSide(xs: Array[Double], ys: Array[Double], normalXs: Array[Double], normalYs: Array[Double],
      count: Int, x: Double, y: Double): Int =
    var best = Double.NegativeInfinity
    var side = 0
    var i = 0
    while i < count do
      val distance = sideDistance(xs, ys, normalXs, normalYs, i, x, y)
      if distance > best then
        best = distance
        side = i
      i += 1
    side
