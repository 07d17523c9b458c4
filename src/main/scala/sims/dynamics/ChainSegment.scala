package sims.dynamics

import sims.geometry.Vector2D

/** One edge of a chain: a polyline of edges for terrain, made with [[ChainSegment.chain]]. Unlike
  * a lone [[Edge]] it is one-sided, its solid side to the right of its direction (a chain drawn
  * from left to right is a ground seen from above), and it knows its neighbours' far ends
  * (`previous`, `next`): under the soft step a shape sliding over the join of two segments meets
  * the chain's surface there, not the corner of the segment it leaves or enters (no "ghost
  * collisions": a box sliding along a flat chain of short segments does not bump at the joins).
  * Under the classic step a chain collides as its edges.
  *
  * Like an edge it has no mass and may only be part of a fixed body.
  */
final class ChainSegment(
    start: Vector2D,
    end: Vector2D,
    /** The previous segment's start, if the chain goes on before `start`. */
    val previous: Option[Vector2D],
    /** The next segment's end, if the chain goes on after `end`. */
    val next: Option[Vector2D]) extends Edge(start, end):
  previous.foreach(Vector2D.requireFinite("previous", _))
  next.foreach(Vector2D.requireFinite("next", _))

  // The neighbours' far ends in the segment's own frame, so that they move with it: along its
  // direction t and its free side's normal f, from start (previous) and from end (next).
  private val directionX = (end.x - start.x) / (2 * halfLength)
  private val directionY = (end.y - start.y) / (2 * halfLength)
  private[sims] val previousAlong: Double = previous.fold(0.0)(p => (p.x - start.x) * directionX + (p.y - start.y) * directionY)
  private[sims] val previousOut: Double = previous.fold(0.0)(p => (p.y - start.y) * directionX - (p.x - start.x) * directionY)
  private[sims] val nextAlong: Double = next.fold(0.0)(p => (p.x - end.x) * directionX + (p.y - end.y) * directionY)
  private[sims] val nextOut: Double = next.fold(0.0)(p => (p.y - end.y) * directionX - (p.x - end.x) * directionY)

  override def toString: String =
    s"ChainSegment(from $vertex1 to $vertex2${previous.fold("")(p => s", after $p")}${next.fold("")(n => s", before $n")})"

/** Chains of segments. */
object ChainSegment:
  /** The segments of the polyline through `points` (world coordinates, at least two, each
    * distinct from the one before), each knowing its neighbours; with `loop` the last point
    * joins the first (at least three points). Add them to one fixed body:
    * `Body(ChainSegment.chain(points)*)`.
    */
  def chain(points: Seq[Vector2D], loop: Boolean = false): Seq[ChainSegment] =
    val minimum = if loop then 3 else 2
    if points.length < minimum then
      throw IllegalArgumentException(
        s"points must hold at least $minimum points${if loop then " for a loop" else ""}, got ${points.length}")
    for p <- points do Vector2D.requireFinite("points", p)
    val n = points.length
    val count = if loop then n else n - 1
    for i <- 0 until count do
      if points(i) == points((i + 1) % n) then
        throw IllegalArgumentException(s"points must differ from the one before, got ${points(i)} twice at $i")
    def at(i: Int): Option[Vector2D] =
      if loop then Some(points(((i % n) + n) % n)) else if i < 0 || i >= n then None else Some(points(i))
    for i <- 0 until count yield ChainSegment(points(i), points((i + 1) % n), at(i - 1), at(i + 2))
