package sims.dynamics

import scala.collection.mutable.ArrayBuffer
import sims.collision.{Collision, Contact, RayHit, ShapeQueries}
import sims.dynamics.joints.Joint
import sims.geometry.{AABB, Vector2D}

/** A world's queries: its bodies and joints by id and name, the last step's collisions and
  * contacts, and ray casts and box and point queries over its shapes, through the world's
  * broadphase (see [[sims.collision.ShapeQueries]]), which looks at the shapes near the ray or
  * box only. Every query skips sensors unless asked for them with `sensors = true` (a sensor
  * is a region, not a thing a ray or a swept shape would stop at).
  */
trait WorldQueries:
  this: World =>

  // The ids of the bodies (see `bodyById`).
  private[dynamics] val bodyIds = WorldIds()

  /** The body of this world with that `id` (see `Body.id`), if there is one: in a loaded world,
    * the body that had it when the world was saved.
    */
  def bodyById(id: Int): Option[Body] = bodyIds.body(id).filter(_.world eq this)

  /** The first body of this world (in world order) with that `name`, if any. */
  def bodyNamed(name: String): Option[Body] = bodyList.find(_.name.contains(name))

  /** The first joint of this world (in world order) with that `name`, if any. */
  def jointNamed(name: String): Option[Joint] = jointList.find(_.name.contains(name))

  /** The collisions the detector found last, e.g. to draw them: under the classic step, those
    * after the last position correction of the last step. The soft step does not use them (see
    * `contacts` for either step's). The objects are the detector's own: the built-in detector
    * refills them in place at its next `detect()` or `refresh()`, so they describe the last
    * classic step until the next `step()`; copy what you need to keep.
    */
  def collisions: collection.IndexedSeq[Collision] = detector.collisions

  /** The contacts of the last step as its solver saw them (for either step: the classic
    * step's collisions, the soft step's manifolds with their impulses), as copies that stay
    * valid.
    */
  def contacts: IndexedSeq[Contact] = solver.contacts(this)

  private val queries = ShapeQueries(this)

  /** The nearest shape that the straight path from `from` to `to` enters, among those `filter`
    * accepts (all by default), with where and at what fraction of the way; None if it enters
    * none. Shapes it starts inside are not hit; a user's shape kind is hit only if its class
    * overrides `Shape.rayCast`. Looks at the shapes near the path only (through a grid).
    */
  def rayCast(from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape,
      sensors: Boolean = false): Option[RayHit] =
    queries.rayCast(Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to),
      requireFilter(filter, sensors))

  /** Every shape the path from `from` to `to` enters, as `rayCast` finds them, nearest first
    * (shapes hit at the same fraction in the order they joined the world).
    */
  def rayCastAll(from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape,
      sensors: Boolean = false): IndexedSeq[RayHit] =
    queries.rayCastAll(Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to),
      requireFilter(filter, sensors))

  /** The shapes whose bounding boxes overlap (or touch) `box`, among those `filter` accepts, in
    * the order they joined the world. Looks at the shapes near the box only.
    */
  def query(box: AABB, filter: Shape => Boolean = World.AnyShape, sensors: Boolean = false): IndexedSeq[Shape] =
    if box == null then throw IllegalArgumentException("box must not be null")
    Vector2D.requireFinite("box.minVertex", box.minVertex)
    Vector2D.requireFinite("box.maxVertex", box.maxVertex)
    if box.minVertex.x > box.maxVertex.x || box.minVertex.y > box.maxVertex.y then
      throw IllegalArgumentException(s"box must have its minVertex below and left of its maxVertex, got $box")
    queries.query(box.minVertex.x, box.minVertex.y, box.maxVertex.x, box.maxVertex.y, requireFilter(filter, sensors))

  /** The shapes that contain `point` (world coordinates), among those `filter` accepts, in the
    * order they joined the world (the viewer picks the last free one).
    */
  def shapesAt(point: Vector2D, filter: Shape => Boolean = World.AnyShape, sensors: Boolean = false): IndexedSeq[Shape] =
    queries.shapesAt(Vector2D.requireFinite("point", point), requireFilter(filter, sensors))

  /** The first shape that `shape` meets when swept from `from` to `to` without turning (a
    * circle, a convex polygon such as a box, or a capsule, belonging to no body; at its own
    * `rotation`), among those `filter` accepts: the shape hit, where they meet, the hit shape's
    * outward normal there and the fraction of the path travelled (0 when it overlaps a shape
    * at `from` already); None if it meets none. Looks at the shapes near the path only.
    */
  def castShape(shape: Shape, from: Vector2D, to: Vector2D, filter: Shape => Boolean = World.AnyShape,
      sensors: Boolean = false): Option[RayHit] =
    if shape == null then throw IllegalArgumentException("shape must not be null")
    if shape.body != null then throw IllegalArgumentException(s"shape $shape belongs to a body: cast a shape of its own")
    if !sims.collision.ShapeCast.castable(shape) then
      throw IllegalArgumentException(s"shape must be a circle, a convex polygon or a capsule, got $shape")
    queries.castShape(shape, Vector2D.requireFinite("from", from), Vector2D.requireFinite("to", to),
      requireFilter(filter, sensors))

  /** The shapes that `shape` overlaps exactly (not just by bounds) where it is now, among those
    * `filter` accepts, in the order they joined the world: a shape of the user's own placed with
    * `pos` and `rotation`, or a shape of the world (then its body's shapes are left out).
    * Shapes that only touch do not count. Looks at the shapes near it only.
    */
  def overlapping(shape: Shape, filter: Shape => Boolean = World.AnyShape, sensors: Boolean = false): IndexedSeq[Shape] =
    if shape == null then throw IllegalArgumentException("shape must not be null")
    queries.overlapping(shape, requireFilter(filter, sensors))

  /** `filter`, and unless `sensors` is true, no sensor (queries skip sensors by default). */
  private def requireFilter(filter: Shape => Boolean, sensors: Boolean): Shape => Boolean =
    if filter == null then throw IllegalArgumentException("filter must not be null")
    if sensors then filter else s => !s.sensor && filter(s)

  /** Tells the queries that shapes moved, joined or left: they take the bounds again when next asked. */
  private[sims] def shapesMoved(): Unit = queries.stale = true

  /** Adds to `found`, in world order, every shape (collidable or not) whose bounds overlap the
    * box: the query grid's answer, without a filter or a copy (for the library's own stages).
    */
  private[sims] def shapesNear(minX: Double, minY: Double, maxX: Double, maxY: Double,
      found: ArrayBuffer[Shape]): Unit =
    queries.near(minX, minY, maxX, maxY, found)
