package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.collision.{RayHit, ShapeQueries}
import sims.geometry.{AABB, Vector2D}

/** A world's queries: ray casts and box and point queries over its shapes, through the world's
  * broadphase (see [[sims.collision.ShapeQueries]]), which looks at the shapes near the ray or
  * box only.
  */
trait WorldQueries:
  this: World =>

  private val queries = ShapeQueries(this)

  /** The nearest shape that the straight path from `from` to `to` enters, among those `filter`
    * accepts (all by default), with where and at what fraction of the way; None if it enters
    * none. Shapes it starts inside are not hit; a user's shape kind is hit only if its class
    * overrides `Shape.rayCast`. Looks at the shapes near the path only (through a grid).
    */
  def rayCast(from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape): Option[RayHit] =
    queries.rayCast(Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to), requireFilter(filter))

  /** Every shape the path from `from` to `to` enters, as `rayCast` finds them, nearest first
    * (shapes hit at the same fraction in the order they joined the world).
    */
  def rayCastAll(from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape): IndexedSeq[RayHit] =
    queries.rayCastAll(Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to), requireFilter(filter))

  /** The shapes whose bounding boxes overlap (or touch) `box`, among those `filter` accepts, in
    * the order they joined the world. Looks at the shapes near the box only.
    */
  def query(box: AABB, filter: Shape => Boolean = World.AnyShape): IndexedSeq[Shape] =
    if box == null then throw IllegalArgumentException("box must not be null")
    Vector2D.requireFinite("box.minVertex", box.minVertex)
    Vector2D.requireFinite("box.maxVertex", box.maxVertex)
    if box.minVertex.x > box.maxVertex.x || box.minVertex.y > box.maxVertex.y then
      throw IllegalArgumentException(s"box must have its minVertex below and left of its maxVertex, got $box")
    queries.query(box.minVertex.x, box.minVertex.y, box.maxVertex.x, box.maxVertex.y, requireFilter(filter))

  /** The shapes that contain `point` (world coordinates), among those `filter` accepts, in the
    * order they joined the world (the viewer picks the last free one).
    */
  def shapesAt(point: Vector2D, filter: Shape => Boolean = World.AnyShape): IndexedSeq[Shape] =
    queries.shapesAt(Vector2D.requireFinite("point", point), requireFilter(filter))

  private def requireFilter(filter: Shape => Boolean): Shape => Boolean =
    if filter == null then throw IllegalArgumentException("filter must not be null")
    filter

  /** Tells the queries that shapes moved, joined or left: they take the bounds again when next asked. */
  private[sims] def shapesMoved(): Unit = queries.stale = true

  /** Adds to `found`, in world order, every shape (collidable or not) whose bounds overlap the
    * box: the query grid's answer, without a filter or a copy (for the library's own stages).
    */
  private[sims] def shapesNear(minX: Double, minY: Double, maxX: Double, maxY: Double,
      found: ArrayBuffer[Shape]): Unit =
    queries.near(minX, minY, maxX, maxY, found)
