package sims.collision

import sims.Defaults
import sims.dynamics.{Circle, RoundedSegment, Shape}
import sims.geometry.ConvexPolygon

/** Sweeps a shape that belongs to no body along a straight path and finds where it first meets
  * another shape: conservative advancement, as the bullets' [[TimeOfImpact]] does. At a fraction
  * t of the path the two are `s` apart along the normal n from the cast shape towards the other
  * ([[ShapeSeparation]]); moving by the path d, no point of the cast shape closes faster than
  * d . n per unit of fraction (it does not turn), so advancing by (s - target) / (d . n) never
  * passes the target gap ([[Defaults.LinearSlop]] / 4). A path that does not close on the other
  * shape (d . n at most 0) misses it.
  */
private[sims] final class ShapeCast:
  private val separation = ShapeSeparation()
  /** Set by a hit of `fraction`: the point where the shapes meet and the other shape's normal there. */
  var pointX, pointY, normalX, normalY = 0.0

  /** The fraction of the path from (x0, y0) by (dx, dy) at which `cast` (placed at rotation
    * `angle`) first meets `other`, at most `limit`, or a value above `limit` if it does not (also
    * when a shape is of a kind the separation does not know). Fraction 0 when they overlap at the
    * start. Leaves `cast` placed where it searched last.
    */
  def fraction(cast: Shape, x0: Double, y0: Double, angle: Double, dx: Double, dy: Double, other: Shape,
      limit: Double): Double =
    val target = 0.25 * Defaults.LinearSlop
    var t = 0.0
    var iteration = 0
    var result = Double.PositiveInfinity
    var searching = true
    while searching do
      cast.place(x0 + t * dx, y0 + t * dy, angle)
      if !separation.measure(cast, other) then searching = false
      else
        val s = separation.distance
        val nx = separation.normalX
        val ny = separation.normalY
        if s <= target || iteration == ShapeCast.Iterations then
          if s <= target then
            result = t
            meet(cast, nx, ny, math.max(s, 0))
          searching = false
        else
          val rate = dx * nx + dy * ny
          if rate <= 0 then searching = false
          else
            t += (s - target) / rate
            if t > limit then searching = false
        iteration += 1
    result

  /** The point where `cast` meets the other shape: its outline's farthest point along n, moved
    * by the remaining gap; the other shape's normal is -n.
    */
  private def meet(cast: Shape, nx: Double, ny: Double, gap: Double): Unit =
    normalX = -nx
    normalY = -ny
    cast match
      case circle: Circle =>
        pointX = circle.pos.x + (circle.radius + gap) * nx
        pointY = circle.pos.y + (circle.radius + gap) * ny
      case segment: RoundedSegment =>
        farthest(segment.coreXs, segment.coreYs, 2, nx, ny)
        pointX += (segment.radius + gap) * nx
        pointY += (segment.radius + gap) * ny
      case polygon: ConvexPolygon =>
        farthest(polygon.vertexXs, polygon.vertexYs, polygon.vertexCount, nx, ny)
        pointX += gap * nx
        pointY += gap * ny
      case _ =>
        pointX = cast.pos.x
        pointY = cast.pos.y

  /** Into (pointX, pointY): the middle of the vertices farthest along (nx, ny) (a side facing
    * n gives its middle, a corner itself).
    */
  private def farthest(xs: Array[Double], ys: Array[Double], count: Int, nx: Double, ny: Double): Unit =
    var best = Double.NegativeInfinity
    var i = 0
    while i < count do
      best = math.max(best, xs(i) * nx + ys(i) * ny)
      i += 1
    var sumX, sumY = 0.0
    var n = 0
    i = 0
    while i < count do
      if xs(i) * nx + ys(i) * ny >= best - ShapeCast.SideTolerance then
        sumX += xs(i); sumY += ys(i); n += 1
      i += 1
    pointX = sumX / n
    pointY = sumY / n

private[sims] object ShapeCast:
  /** The most advancement steps of one pair: convex shapes converge in a few. */
  val Iterations = 50
  /** Vertices within this of the farthest along the normal count as the side facing it, m. */
  val SideTolerance = 1e-9

  /** Whether `shape` is of a kind that can be cast: a circle, a convex polygon, a capsule. */
  def castable(shape: Shape): Boolean = shape match
    case _: Circle | _: ConvexPolygon | _: RoundedSegment => true
    case _ => false

  /** The overlap of two shapes: true when the separation measures them overlapping (by more
    * than touching), false when apart or of a kind it does not know.
    */
  def overlap(separation: ShapeSeparation, a: Shape, b: Shape): Boolean =
    separation.measure(a, b) && separation.distance < 0
