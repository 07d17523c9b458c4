package sims.scenes

import sims.dynamics.{Shape, World}
import sims.dynamics.joints.{DistanceJoint, RevoluteJoint}
import sims.geometry.{PortableMath, Vector2D}

/** The outline of a layout body's one shape, centred on the body's centre, never rotated. */
enum Outline:
  /** A disc of this radius, m. */
  case Circle(radius: Double)
  /** An axis-aligned box of these half extents, m. */
  case Box(halfWidth: Double, halfHeight: Double)

/** One body of a [[Layout]]: a single shape, its material, and whether the body is fixed.
  *
  * @param density kg/m^2; 0 for a fixed body, whose mass plays no part (see [[massDensity]])
  * @param friction the shape's coefficient as Box2D, jBox2D and dyn4j take it: they give a
  *   touching pair the geometric mean of the two values. SiMS multiplies the two shapes'
  *   values, so its shapes get the square root: the product is then the same mean.
  * @param restitution the shape's coefficient: the peers give a pair the larger value, SiMS
  *   (square roots, as for friction) the geometric mean; the same when the values are equal,
  *   as in every layout here (a [[Drop]] gives both its shapes the pair's value).
  * @param noCollideGroup 0: collides with every other body; g > 0: with none of group g
  *   (as Box2D's negative group index -g).
  * @param velocity the body's linear velocity at the start, m/s
  */
final case class SceneBody(outline: Outline, centre: Vector2D, fixed: Boolean, density: Double, friction: Double,
    restitution: Double, noCollideGroup: Int = 0, velocity: Vector2D = Vector2D.Null):
  require(if fixed then density >= 0 else density > 0, s"density $density of a ${if fixed then "fixed" else "free"} body")
  require(!fixed || velocity == Vector2D.Null, s"a fixed body with velocity $velocity")
  require(friction >= 0 && restitution >= 0, s"friction $friction, restitution $restitution")
  require(noCollideGroup >= 0, s"no-collide group $noCollideGroup")

  /** The density to give an engine that wants a positive one on every shape (SiMS): the
    * body's own, or [[Layout.FixedBodyDensity]] for a fixed body without one.
    */
  def massDensity: Double = if density > 0 then density else Layout.FixedBodyDensity

/** Bodies of the standard material of the benchmark and golden scenes: friction 0.5,
  * restitution 0, density 1 (0 when fixed), as the reference program's scene builder makes them.
  */
object SceneBody:
  /** An axis-aligned box of the standard material. */
  def box(centre: Vector2D, halfWidth: Double, halfHeight: Double, fixed: Boolean = false): SceneBody =
    standard(Outline.Box(halfWidth, halfHeight), centre, fixed, 0)

  /** A square box of the standard material, `halfSide` each way from its centre. */
  def square(centre: Vector2D, halfSide: Double): SceneBody = box(centre, halfSide, halfSide)

  /** A circle of the standard material, in no-collide group `noCollideGroup`. */
  def circle(centre: Vector2D, radius: Double, fixed: Boolean = false, noCollideGroup: Int = 0): SceneBody =
    standard(Outline.Circle(radius), centre, fixed, noCollideGroup)

  private def standard(outline: Outline, centre: Vector2D, fixed: Boolean, group: Int): SceneBody =
    SceneBody(outline, centre, fixed, if fixed then 0 else 1, Layout.StandardFriction, 0, group)

/** The kinds of joint a [[Layout]] holds. */
enum JointKind:
  /** A rigid distance joint holding the two centres at their initial distance. */
  case Distance
  /** A pin (revolute joint) at the middle of the two centres, about which both turn freely. */
  case Revolute

/** A joint between the layout's bodies `body1` and `body2` (indices into [[Layout.bodies]]):
  * by default a rigid distance joint holding their centres at their initial distance; the two
  * never collide.
  */
final case class SceneJoint(body1: Int, body2: Int, kind: JointKind = JointKind.Distance)

/** A scene described as plain values, which any engine can build: SiMS here ([[world]]),
  * jBox2D and dyn4j in the bench, each by translating the same values. Mirrors the scene
  * description of Box2D v3's reference program (`shared/peers/box2d-v3/scenes.c`).
  *
  * @param bodies every body in creation order (its index names it in joints and in results)
  * @param joints distance joints between body centres
  * @param gravity m/s^2
  * @param timeStep s
  * @param bounds where the free bodies' centres are expected to stay (e.g. a container's inside)
  */
final case class Layout(bodies: IndexedSeq[SceneBody], joints: IndexedSeq[SceneJoint], gravity: Vector2D,
    timeStep: Double, bounds: Region):
  for j <- joints do
    require(j.body1 != j.body2 && bodies.indices.contains(j.body1) && bodies.indices.contains(j.body2), s"joint $j")
  require(timeStep > 0, s"time step $timeStep")

  /** Indices of the free (not fixed) bodies, in order. */
  def freeBodies: IndexedSeq[Int] = bodies.indices.filterNot(bodies(_).fixed)

  /** A revolute joint's pin: the middle of its bodies' initial centres. */
  def pin(joint: SceneJoint): Vector2D = (bodies(joint.body1).centre + bodies(joint.body2).centre) / 2

  /** Rest length of a joint: the initial distance of its bodies' centres, m. */
  def length(joint: SceneJoint): Double =
    val a = bodies(joint.body1).centre
    val b = bodies(joint.body2).centre
    PortableMath.hypot(b.x - a.x, b.y - a.y)

  /** A fresh SiMS world of this layout: its bodies in order (index i is `world.bodies(i)`),
    * then its joints.
    */
  def world(): World =
    val world = World()
    world.timeStep = timeStep
    world.gravity = gravity
    val shapes = bodies.map(shape)
    for group <- bodies.map(_.noCollideGroup).distinct if group > 0 do
      val members = bodies.indices.filter(bodies(_).noCollideGroup == group).map(shapes)
      // A group of every body collides with nothing: off for the broadphase altogether.
      if members.size == shapes.size then members.foreach(_.collidable = false)
      else members.foreach(s => s.transientShapes = members.toSet - s)
    for (spec, shape) <- bodies.zip(shapes) do
      val body = shape.asBody
      if spec.fixed then body.fixed = true
      else if spec.velocity != Vector2D.Null then body.linearVelocity = spec.velocity
      world += body
    val created = world.bodies.toIndexedSeq
    for j <- joints do
      val (a, b) = (created(j.body1), created(j.body2))
      j.kind match
        case JointKind.Distance => world += DistanceJoint(a, a.pos, b, b.pos)
        case JointKind.Revolute => world += RevoluteJoint(a, b, pin(j))
    world

  private def shape(spec: SceneBody): Shape =
    val shape = spec.outline match
      case Outline.Circle(radius) => sims.dynamics.Circle(radius, spec.massDensity)
      case Outline.Box(halfWidth, halfHeight) => sims.dynamics.Rectangle(halfWidth, halfHeight, spec.massDensity)
    shape.pos = spec.centre
    // SiMS multiplies the two shapes' values: square roots give the pair their geometric mean.
    shape.friction = math.sqrt(spec.friction)
    shape.restitution = math.sqrt(spec.restitution)
    shape

object Layout:
  /** Density given to the shapes of a fixed body of density 0 by an engine that wants a
    * positive one; any value would do, since a fixed body's mass is never used.
    */
  val FixedBodyDensity: Double = 1.0

  /** Gravity of the benchmark and golden scenes (SiMS's default), m/s^2. */
  val StandardGravity: Vector2D = sims.Defaults.Gravity

  /** Time step of the benchmark and golden scenes (SiMS's default), s. */
  val StandardTimeStep: Double = sims.Defaults.TimeStep

  /** Friction of every shape of the benchmark and golden scenes: 0.5 for every pair. */
  val StandardFriction: Double = 0.5

/** A scene given as a [[Layout]]: SiMS builds it here, the bench's peers from the same layout. */
trait LayoutScene extends Scene:
  /** The scene's bodies, joints and settings. */
  def layout: Layout

  /** The layout's bounds. */
  override def region: Region = layout.bounds

  def build(): Staged = Staged(layout.world())
