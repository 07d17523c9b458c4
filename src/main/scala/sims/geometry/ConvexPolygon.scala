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
    val xs = vertexXs
    val ys = vertexYs
    Projection(axis, PolygonMath.projectionMin(xs, ys, xs.length, axis.x, axis.y),
      PolygonMath.projectionMax(xs, ys, xs.length, axis.x, axis.y))

  /** The smallest axis-aligned box holding this polygon. */
  def AABB: AABB =
    val xs = vertexXs
    val ys = vertexYs
    new sims.geometry.AABB(Vector2D(xs.min, ys.min), Vector2D(xs.max, ys.max))

  /** True if `point` lies inside this polygon or on its boundary. */
  def contains(point: Vector2D): Boolean =
    val xs = vertexXs
    PolygonMath.contains(xs, vertexYs, xs.length, point.x, point.y)

  /** Number of vertices (hot-loop access without building `vertices`). */
  private[sims] def vertexCount: Int = vertices.length

  /** The x coordinates of the vertices as an array, for the narrowphase's loops: not to be
    * modified, and valid until the polygon moves. This default builds a new array.
    */
  private[sims] def vertexXs: Array[Double] = vertices.iterator.map(_.x).toArray

  /** The y coordinates of the vertices as an array (see `vertexXs`). */
  private[sims] def vertexYs: Array[Double] = vertices.iterator.map(_.y).toArray

  /** The x components of the outward unit side normals as an array (see `vertexXs`). */
  private[sims] def sideNormalXs: Array[Double] =
    val xs = vertexXs
    val ys = vertexYs
    Array.tabulate(xs.length)(PolygonMath.sideNormalX(xs, ys, xs.length, _))

  /** The y components of the outward unit side normals as an array (see `vertexXs`). */
  private[sims] def sideNormalYs: Array[Double] =
    val xs = vertexXs
    val ys = vertexYs
    Array.tabulate(xs.length)(PolygonMath.sideNormalY(xs, ys, xs.length, _))
