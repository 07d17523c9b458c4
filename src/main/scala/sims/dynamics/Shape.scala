package sims.dynamics

import sims.collision.RayHit
import sims.geometry.{AABB, ConvexPolygon, PortableMath, Projection, RayMath, Vector2D}

/** A rigid two-dimensional form with a material (density, restitution, friction). Bodies are
  * made of shapes; a shape belongs to at most one body. Subclasses give the geometry:
  * `volume` (the area), `I` (moment of inertia about the shape's own centre), `AABB`,
  * `project` and `contains`.
  */
abstract class Shape:

  /** Density in kg/m^2; positive and finite. */
  val density: Double

  /** Area in m^2 (called volume as in "mass = volume * density"). */
  def volume: Double

  /** Moment of inertia about the shape's own centre, in kg m^2. */
  def I: Double

  /** Mass: volume times density. */
  def mass: Double = volume * density

  // The narrowphase picks a pair's methods by the shapes' classes, for every candidate pair of
  // every step: read once here, because on Scala.js getClass is a type switch and a lookup.
  private[sims] final val shapeClass: Class[?] = getClass

  // World frame placement; kept as plain doubles so the solver moves shapes without allocating.
  private[sims] var x: Double = 0
  private[sims] var y: Double = 0
  private[sims] var angle: Double = 0

  /** Position of the shape's centre, world coordinates. */
  def pos: Vector2D = Vector2D(x, y)

  /** Moves the shape; if it belongs to a body, the body's centre of mass and inertia follow.
    * Fails once the body is in a world (its shapes are then fixed).
    */
  def pos_=(newPos: Vector2D): Unit =
    Vector2D.requireFinite("pos", newPos)
    checkNotInWorld("pos")
    replace(newPos.x, newPos.y, angle)

  /** Rotation of the shape in radians, counter-clockwise, world frame. */
  def rotation: Double = angle

  /** Rotates the shape about its own centre; same rules as `pos_=`. */
  def rotation_=(newRotation: Double): Unit =
    Vector2D.requireFinite("rotation", newRotation)
    checkNotInWorld("rotation")
    replace(x, y, newRotation)

  private var _restitution = sims.Defaults.Restitution

  /** Coefficient of restitution; a collision uses the product of both shapes' values. */
  def restitution: Double = _restitution

  /** Sets the restitution; must be finite and at least 0. */
  def restitution_=(value: Double): Unit =
    Shape.requireNonNegative("restitution", value)
    _restitution = value

  private var _friction = sims.Defaults.Friction

  /** Coefficient of friction; a collision uses the product of both shapes' values. */
  def friction: Double = _friction

  /** Sets the friction; must be finite and at least 0. */
  def friction_=(value: Double): Unit =
    Shape.requireNonNegative("friction", value)
    _friction = value

  /** Whether this shape's contacts are reported as contact events (default true); off, its
    * pairs make no `World.contactEvents` (a touching pair ends at the next step). Its contacts
    * are solved all the same.
    */
  def enableContactEvents: Boolean = _enableContactEvents

  /** Switches this shape's contact events; the next step looks at its pairs again, even in a
    * world whose bodies all sleep.
    */
  def enableContactEvents_=(value: Boolean): Unit =
    _enableContactEvents = value
    if _body != null && _body.world != null then _body.world.eventSwitchChanged()

  private var _enableContactEvents = true

  /** Anything of the user's that belongs with this shape (default None): never read by the library. */
  var userData: Option[Any] = None

  /** Whether this shape takes part in collisions at all. */
  var collidable: Boolean = true

  private var _sensor = false

  /** Whether this shape is a sensor (default false): it never pushes nor is pushed (it takes
    * no part in contacts, under either step), and the world reports the shapes that begin and
    * stop overlapping it as `World.sensorEvents`. Its mass counts for its body as any shape's.
    */
  def sensor: Boolean = _sensor

  /** Makes the shape a sensor or a solid shape again, at any time: from the next step, its
    * contacts end (becoming a sensor) or its overlaps end (becoming solid), each with its event.
    */
  def sensor_=(value: Boolean): Unit =
    if value != _sensor then
      _sensor = value
      if body != null && body.world != null then body.world.sensorChanged(value)

  /** Shapes this one never collides with (checked in both directions). */
  var transientShapes: Set[Shape] = Set.empty

  // Collision filtering (Box2D's rule, see sims.collision.PairFilter). Every Int is a valid
  // value of each, so there is nothing to check.

  /** The collision categories this shape belongs to, one bit each (default 1: the first). */
  var categoryBits: Int = sims.Defaults.CategoryBits

  /** The categories this shape collides with, one bit each (default -1: all). Two shapes
    * collide only if each one's mask has a bit of the other's categories (unless a group
    * decides).
    */
  var maskBits: Int = sims.Defaults.MaskBits

  /** The collision group (default 0: none). Two shapes of the same positive group always
    * collide, two of the same negative group never; otherwise categories and masks decide.
    */
  var groupIndex: Int = sims.Defaults.GroupIndex

  private[sims] var _body: Body = null

  /** The body this shape belongs to, or null before it is part of one. */
  def body: Body = _body

  /** Order in which the shape joined a world (-1 outside any world); orders broadphase pairs. */
  private[sims] var worldIndex: Int = -1

  /** The smallest axis-aligned box around the shape. */
  def AABB: AABB

  /** The largest distance from the shape's centre to a point of the shape (an upper bound will
    * do): how far a point of it can move when it turns. This default takes half the diagonal of
    * the current AABB.
    */
  private[sims] def boundingRadius: Double =
    val box = AABB
    0.5 * PortableMath.hypot(box.maxVertex.x - box.minVertex.x, box.maxVertex.y - box.minVertex.y)

  /** The interval the shape covers on `axis`. */
  def project(axis: Vector2D): Projection

  /** True if `point` (world coordinates) lies inside or on the shape. */
  def contains(point: Vector2D): Boolean

  /** Where the straight path from `from` to `to` (world coordinates) first enters this shape,
    * or None if it misses the shape or starts inside it. Circles, polygons (any shape that mixes
    * in `ConvexPolygon`), capsules and edges are cast exactly. Any other shape is missed, unless
    * its class overrides this method: `World.rayCast` then asks it too.
    */
  def rayCast(from: Vector2D, to: Vector2D): Option[RayHit] =
    Vector2D.requireFinite("from", from)
    Vector2D.requireFinite("to", to)
    val hit = RayMath.Hit()
    val dx = to.x - from.x
    val dy = to.y - from.y
    if castRay(from.x, from.y, dx, dy, 1, hit) then
      Some(RayHit(this, Vector2D(from.x + hit.fraction * dx, from.y + hit.fraction * dy),
          Vector2D(hit.normalX, hit.normalY), hit.fraction))
    else None

  /** The library's allocation-free ray cast (see [[sims.geometry.RayMath]]): fills `hit` and is
    * true when the ray from (x1, y1) along (dx, dy) enters the shape at a fraction at most
    * `maxFraction`. By default the sides of a `ConvexPolygon`, else a miss; the library's other
    * shapes override it.
    */
  private[sims] def castRay(x1: Double, y1: Double, dx: Double, dy: Double, maxFraction: Double,
      hit: RayMath.Hit): Boolean =
    this match
      case polygon: ConvexPolygon =>
        val xs = polygon.vertexXs
        RayMath.polygon(xs, polygon.vertexYs, polygon.sideNormalXs, polygon.sideNormalYs, xs.length, x1, y1, dx, dy,
          maxFraction, hit)
      case _ => false

  /** A new body made of this shape alone. */
  def asBody: Body = Body(this)

  /** Sets the world placement; subclasses drop their cached geometry. */
  private[sims] def place(newX: Double, newY: Double, newAngle: Double): Unit =
    x = newX
    y = newY
    angle = newAngle
    moved()

  /** Called after every change of placement; shapes with cached geometry invalidate it. A soft
    * step with several workers places many bodies' shapes at once, on its threads: an override
    * should touch only its own shape's state.
    */
  protected def moved(): Unit = ()

  /** Computes the geometry the shape caches for the collision stage now, if it moved since: the
    * threads of a shared collision stage then only read it.
    */
  private[sims] def refreshCaches(): Unit = ()

  /** Computes the bounds the shape caches (a polygon's world vertices and box) now, if it moved
    * since: a stage that moves many bodies at once on several threads leaves them current for
    * the broadphase, which then only reads them.
    */
  private[sims] def refreshBounds(): Unit = ()

  /** Lowest projection of the shape on the unit axis (ax, ay) (allocation-free). */
  private[sims] def projectMin(ax: Double, ay: Double): Double = project(Vector2D(ax, ay)).lower
  /** Highest projection of the shape on the unit axis (ax, ay). */
  private[sims] def projectMax(ax: Double, ay: Double): Double = project(Vector2D(ax, ay)).upper

  /** Lower x bound of the AABB (allocation-free, for the broadphase). */
  private[sims] def minX: Double = AABB.minVertex.x
  /** Lower y bound of the AABB. */
  private[sims] def minY: Double = AABB.minVertex.y
  /** Upper x bound of the AABB. */
  private[sims] def maxX: Double = AABB.maxVertex.x
  /** Upper y bound of the AABB. */
  private[sims] def maxY: Double = AABB.maxVertex.y

  /** Moves the shape and lets its body recompute mass and centre; if the body cannot (its centre
    * or inertia would overflow), the shape goes back where it was and the error is rethrown.
    */
  private def replace(newX: Double, newY: Double, newAngle: Double): Unit =
    val (oldX, oldY, oldAngle) = (x, y, angle)
    place(newX, newY, newAngle)
    if body != null then
      try body.shapesChanged()
      catch
        case e: IllegalArgumentException =>
          place(oldX, oldY, oldAngle)
          body.shapesChanged()
          throw e

  private def checkNotInWorld(what: String): Unit =
    if body != null && body.world != null then
      throw IllegalArgumentException(
        s"cannot change the $what of a shape whose body is already in a world")

/** Checks shared by all shapes. */
object Shape:
  /** True unless `shape` is of one of the library's final shape classes, whose `rayCast` is the
    * library's own: ray casts then call `rayCast`, which a user's class may override (without
    * reflection, which Scala.js lacks, an override cannot be seen; calling a `rayCast` that is
    * not overridden gives the same hit as the library's cast, only with its allocations).
    */
  private[sims] def castsItself(shape: Shape): Boolean = shape match
    case _: Circle | _: Rectangle | _: RegularPolygon | _: HullPolygon | _: Capsule | _: Edge => false
    case _ => true

  /** Fails unless `value` is finite and strictly positive. */
  private[sims] def requirePositive(name: String, value: Double): Double =
    // java.lang.Double's static tests: `value.isInfinite` would box the value (the broadphase
    // checks its grid side with this at every step).
    if !(value > 0) || java.lang.Double.isInfinite(value) then
      throw IllegalArgumentException(s"$name must be positive and finite, got $value")
    value

  /** Fails unless a quantity computed from a shape's or body's arguments (volume, mass,
    * inertia) is positive and finite with a finite inverse: arguments that each pass their own
    * check can still overflow (a radius of 1e200 squared) or underflow (1e-300 squared) in the
    * product, and the solvers divide by mass and inertia. `owner` (by name) is built only for
    * the error: bodies are made in numbers during a game, and describing one lists its shapes.
    */
  private[sims] def requireDerived(owner: => String, name: String, value: Double): Double =
    if !(value > 0) || java.lang.Double.isInfinite(value) || java.lang.Double.isInfinite(1 / value) then
      throw IllegalArgumentException(
        s"$owner: its $name would be $value, not a positive finite number with a finite inverse; " +
          "the arguments are too large or too small")
    value

  /** Brings the cached geometry (`refreshCaches`) of `shapes(from until until)` up to date: what a
    * stage that reads shapes on several threads at once does first, in ranges, so that no read
    * writes a shape.
    */
  private[sims] def refreshCaches(shapes: Array[Shape], from: Int, until: Int): Unit =
    var i = from
    while i < until do
      shapes(i).refreshCaches()
      i += 1

  /** Fails unless a shape's volume, mass and moment of inertia are usable (see `requireDerived`).
    * `arguments` (by name: the shape's description) is built only for the error.
    */
  private[dynamics] def checkDerived(shape: Shape, arguments: => String): Unit =
    requireDerived(arguments, "volume", shape.volume)
    requireDerived(arguments, "mass", shape.mass)
    requireDerived(arguments, "moment of inertia", shape.I)

  /** Fails unless `value` is finite and at least 0. */
  private[sims] def requireNonNegative(name: String, value: Double): Double =
    if !(value >= 0) || java.lang.Double.isInfinite(value) then
      throw IllegalArgumentException(s"$name must be finite and at least 0, got $value")
    value
