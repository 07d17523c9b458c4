package sims.scenes

import sims.dynamics.{Body, World}
import sims.geometry.{PortableMath, Vector2D}

/** An axis-aligned region of the world, in metres: a camera's view or the space a scene's
  * bodies are expected to stay in.
  */
final case class Region(minX: Double, minY: Double, maxX: Double, maxY: Double):
  require(minX < maxX && minY < maxY, s"empty region ($minX, $minY) .. ($maxX, $maxY)")

  /** Width in metres. */
  def width: Double = maxX - minX

  /** Height in metres. */
  def height: Double = maxY - minY

  /** The centre point. */
  def centre: Vector2D = Vector2D((minX + maxX) / 2, (minY + maxY) / 2)

  /** True if the point lies inside or on the border. */
  def contains(point: Vector2D): Boolean =
    point.x >= minX && point.x <= maxX && point.y >= minY && point.y <= maxY

/** Something a scene can do on request while it runs, e.g. fire the cannon. */
final case class SceneAction(label: String, run: () => Unit)

/** A scene built and ready to step: its world, its optional action, and what to draw over its
  * bodies as it is now (`overlay()`, asked for every picture).
  */
final case class Staged(world: World, action: Option[SceneAction] = None, overlay: () => Overlay = () => Overlay.empty)

/** A scene: a recipe for a fresh world, with the view a camera should show and the region its
  * bodies are expected to stay in (checked by the tests). The examples, the benchmarks and the
  * tests all build their worlds from scenes; [[Scenes.find]] finds any of them by name.
  */
trait Scene:
  /** Short name used on the command line, in the viewer and by the bench, e.g. "BallStack". */
  def name: String

  /** One sentence saying what the scene shows. */
  def description: String

  /** The part of the world a camera shows by default. */
  def view: Region

  /** Where every body's centre must stay during the first seconds (the tests check 5 s). */
  def region: Region = view

  /** Whether the scene runs under the soft step only. Such a scene shows what only the soft
    * step has (motors, springs, joints that break, wheel, weld and motor joints): the classic
    * step, SiMS 1.2's algorithm, cannot step them, so the scene's world comes with `SoftStep()`
    * chosen, switching it to `ClassicStep` fails with the library's error, and the examples,
    * the viewer and the playground offer it the soft step alone. Default false: both steps.
    */
  def softStepOnly: Boolean = false

  /** Builds a fresh world for this scene (every call gives an independent one); a
    * `softStepOnly` scene's world has `SoftStep()` as its solver already.
    */
  def build(): Staged

/** Building blocks shared by the scenes and by the tests that set up small worlds. */
object Scene:
  /** A fixed box centred at `centre`, rotated by `rotation` (e.g. ground, walls, slopes). */
  def fixedBox(centre: Vector2D, halfWidth: Double, halfHeight: Double, rotation: Double = 0): Body =
    val box = sims.dynamics.Rectangle(halfWidth, halfHeight, 1)
    box.pos = centre
    box.rotation = rotation
    val body = box.asBody
    body.fixed = true
    body

  /** A fixed ground box whose top face is at y = 0, spanning x in [-halfWidth, halfWidth]
    * shifted by `centreX`.
    */
  def ground(halfWidth: Double, centreX: Double = 0): Body =
    fixedBox(Vector2D(centreX, -0.5), halfWidth, 0.5)

  /** A fixed ground (top face at y = 0, `halfWidth` each side of x = 0) and two fixed walls
    * 0.5 m thick standing on it, `height` high, whose inner faces are `inner` from the middle.
    */
  def container(halfWidth: Double, inner: Double, height: Double): Seq[Body] =
    ground(halfWidth) +: Seq(-(inner + 0.25), inner + 0.25).map(x => fixedBox(Vector2D(x, height / 2), 0.25, height / 2))

  /** A fixed plank of thickness 2 `halfThickness` whose top face runs from `from` to `to`. */
  def ramp(from: Vector2D, to: Vector2D, halfThickness: Double = 0.25): Body =
    val along = (to - from).unit
    val centre = (from + to) / 2 - along.leftNormal * halfThickness
    fixedBox(centre, (to - from).length / 2, halfThickness, PortableMath.atan2(along.y, along.x))

  /** A free circle body of the given radius and density centred at `centre`. */
  def ball(centre: Vector2D, radius: Double, density: Double = 1): Body =
    val circle = sims.dynamics.Circle(radius, density)
    circle.pos = centre
    circle.asBody

  /** A free box body centred at `centre`. */
  def box(centre: Vector2D, halfWidth: Double, halfHeight: Double, density: Double = 1): Body =
    val rectangle = sims.dynamics.Rectangle(halfWidth, halfHeight, density)
    rectangle.pos = centre
    rectangle.asBody

  /** A world stepped by `SoftStep()` (for a `softStepOnly` scene), with the given bodies added
    * in order; the solver comes first, so that joints only the soft step has may join it.
    */
  def softWorldOf(bodies: Body*): World =
    val world = World()
    world.solver = sims.solver.SoftStep()
    bodies.foreach(world += _)
    world

  /** A world with the given bodies added in order. */
  def worldOf(bodies: Body*): World =
    val world = World()
    bodies.foreach(world += _)
    world
