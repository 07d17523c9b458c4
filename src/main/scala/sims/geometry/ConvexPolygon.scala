package sims.geometry

/** A convex polygon given by its vertices in counter-clockwise order. Implemented by polygon
  * shapes; the narrowphase works on this trait, so a user's own convex shape collides with
  * the built-in ones when it mixes it in.
  */
trait ConvexPolygon:

  /** The vertices in counter-clockwise order, in world coordinates. */
  def vertices: IndexedSeq[Vector2D]

  /** The sides: side i goes from vertex i to vertex i + 1; its `n0` points outward. */
  def sides: IndexedSeq[Segment] =
    val vs = vertices
    IndexedSeq.tabulate(vs.length)(i => Segment(vs(i), vs((i + 1) % vs.length)))

  /** The interval this polygon covers on `axis` (in units of `axis`'s length). */
  def project(axis: Vector2D): Projection =
    val vs = vertices
    var lower = Double.PositiveInfinity
    var upper = Double.NegativeInfinity
    var i = 0
    while i < vs.length do
      val p = vs(i) dot axis
      if p < lower then lower = p
      if p > upper then upper = p
      i += 1
    Projection(axis, lower, upper)

  /** The smallest axis-aligned box holding this polygon. */
  def AABB: AABB =
    val vs = vertices
    val xs = vs.map(_.x)
    val ys = vs.map(_.y)
    new sims.geometry.AABB(Vector2D(xs.min, ys.min), Vector2D(xs.max, ys.max))

  /** True if `point` lies inside this polygon or on its boundary. */
  def contains(point: Vector2D): Boolean =
    val vs = vertices
    var i = 0
    var inside = true
    while inside && i < vs.length do
      val a = vs(i)
      val b = vs((i + 1) % vs.length)
      // Inside a counter-clockwise polygon the point is left of (or on) every side.
      if ((b - a) cross (point - a)) < 0 then inside = false
      i += 1
    inside

  /** Number of vertices (hot-loop access without building `vertices`). */
  private[sims] def vertexCount: Int = vertices.length

  /** x coordinate of vertex i (hot-loop access). */
  private[sims] def vertexX(i: Int): Double = vertices(i).x

  /** y coordinate of vertex i (hot-loop access). */
  private[sims] def vertexY(i: Int): Double = vertices(i).y

  /** The x coordinates of the vertices as an array, for the narrowphase's loops: not to be
    * modified, and valid until the polygon moves. This default builds a new array.
    */
  private[sims] def vertexXs: Array[Double] = Array.tabulate(vertexCount)(vertexX)

  /** The y coordinates of the vertices as an array (see `vertexXs`). */
  private[sims] def vertexYs: Array[Double] = Array.tabulate(vertexCount)(vertexY)

  /** The x components of the outward unit side normals as an array (see `vertexXs`). */
  private[sims] def sideNormalXs: Array[Double] = Array.tabulate(vertexCount)(sideNormalX)

  /** The y components of the outward unit side normals as an array (see `vertexXs`). */
  private[sims] def sideNormalYs: Array[Double] = Array.tabulate(vertexCount)(sideNormalY)

  /** x of the outward unit normal of side i (from vertex i to i + 1): the side's right normal. */
  private[sims] def sideNormalX(i: Int): Double =
    val j = if i + 1 == vertexCount then 0 else i + 1
    val dx = vertexX(j) - vertexX(i)
    val dy = vertexY(j) - vertexY(i)
    dy / math.sqrt(dx * dx + dy * dy)

  /** y of the outward unit normal of side i. */
  private[sims] def sideNormalY(i: Int): Double =
    val j = if i + 1 == vertexCount then 0 else i + 1
    val dx = vertexX(j) - vertexX(i)
    val dy = vertexY(j) - vertexY(i)
    -dx / math.sqrt(dx * dx + dy * dy)
