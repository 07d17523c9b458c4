package sims.dynamics

import sims.geometry.{PortableMath, Vector2D}

/** A straight edge of no thickness from `start` to `end` (world coordinates, distinct): the
  * outline of something fixed, a ground, a slope or a wall drawn as a line. It is two-sided:
  * shapes collide with it from either side.
  *
  * An edge has no area, so its mass, area and inertia are 0 and mean nothing; it may only be
  * part of a fixed body: a body with an edge is fixed when it is made, and freeing it fails. Its
  * centre (`pos`) is the middle of the edge, its rotation the direction from start to end.
  *
  * (Named so as not to clash with the geometry's [[sims.geometry.Segment]].)
  */
class Edge(
    /** Where the edge began when it was made (world coordinates). */
    val start: Vector2D,
    /** Where the edge ended when it was made (world coordinates). */
    val end: Vector2D) extends RoundedSegment:
  Vector2D.requireFinite("start", start)
  Vector2D.requireFinite("end", end)
  if start == end then throw IllegalArgumentException(s"end must differ from start, got $end for both")

  /** Half the distance from start to end. */
  val halfLength: Double = (end - start).length / 2

  /** 0: an edge has no thickness. */
  val radius: Double = 0

  /** 0: an edge has no mass. */
  val density: Double = 0

  /** 0: an edge has no area. */
  val volume: Double = 0

  /** 0: an edge has no mass. */
  val I: Double = 0

  place((start.x + end.x) / 2, (start.y + end.y) / 2, PortableMath.atan2(end.y - start.y, end.x - start.x))

  override def toString: String = s"Edge(from $vertex1 to $vertex2)"
