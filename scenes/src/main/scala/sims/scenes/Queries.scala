package sims.scenes

import sims.collision.RayHit
import sims.dynamics.{Capsule, Circle, HullPolygon, Rectangle, RegularPolygon, Shape, World}
import sims.geometry.{AABB, PortableMath, Segment, Vector2D}

/** The world's queries at work: a laser turning above a pile is a ray cast, reflected where it
  * hits (up to [[Queries.Bounces]] times) and pushing the first body it hits; a box query
  * sweeping along the floor highlights the bodies under it. The emitter is a fixed circle that
  * collides with nothing; the beam starts inside it, so it is not hit.
  */
object Queries extends Scene:
  /** Where the beam starts, m. */
  val Emitter: Vector2D = Vector2D(0, 5.5)
  /** How far the beam reaches, reflections included, m. */
  val BeamLength: Double = 16
  /** Reflections of the beam. */
  val Bounces: Int = 3
  /** The beam's turning speed, rad/s, counter-clockwise. */
  val TurnRate: Double = 0.8
  /** The beam's direction at time 0, rad: up and to the left, so that it sweeps down over the
    * pile and points into it, a little right of straight down, at 3 s (the gallery's picture).
    */
  val StartAngle: Double = -math.Pi / 2 + 0.35 - 3 * TurnRate
  /** The push on the first body hit, per kilogram of it (half of gravity: it never lifts one), N/kg. */
  val Push: Double = 4.9

  def name: String = "Queries"
  def description: String = "A turning laser made by ray casts pushes what it hits; a box query highlights the bodies under it."
  def view: Region = Region(-7.5, -1, 7.5, 7)
  override def region: Region = Region(-6, -0.2, 6, 7)

  /** The beam's direction at time `t`. */
  def direction(t: Double): Vector2D =
    val angle = StartAngle + TurnRate * t
    Vector2D(PortableMath.cos(angle), PortableMath.sin(angle))

  /** The beam at the world's time: its pieces, each with the hit it ends at (None for the last
    * piece when it runs out of length).
    */
  def beam(world: World): Seq[(Segment, Option[RayHit])] =
    var start = Emitter
    var heading = direction(world.time)
    var left = BeamLength
    var last: Shape = null
    val pieces = Seq.newBuilder[(Segment, Option[RayHit])]
    var going = true
    var bounce = 0
    while going do
      val end = start + heading * left
      // The shape it leaves is not hit again on the way out.
      val leaving = last
      world.rayCast(start, end, _ ne leaving) match
        case Some(hit) if bounce < Bounces =>
          pieces += ((Segment(start, hit.point), Some(hit)))
          left -= (hit.point - start).length
          heading = heading - hit.normal * (2 * (heading dot hit.normal)) // reflected
          start = hit.point
          last = hit.shape
          bounce += 1
        case hit =>
          pieces += ((Segment(start, hit.map(_.point).getOrElse(end)), hit))
          going = false
    pieces.result()

  /** The box the query sweeps along the floor at time `t`. */
  def zone(t: Double): AABB =
    val x = 4 * PortableMath.sin(0.6 * t)
    AABB(Vector2D(x - 1.25, 0), Vector2D(x + 1.25, 1.6))

  /** The free shapes whose bounds overlap the zone now. */
  def highlighted(world: World): Set[Shape] = world.query(zone(world.time), !_.body.fixed).toSet

  /** Pushes the first body the beam hits, if it is free, along the beam at the point hit. */
  private def push(world: World): Unit =
    beam(world).headOption.flatMap(_._2).foreach { hit =>
      val body = hit.shape.body
      if !body.fixed then body.applyForce(direction(world.time) * (Push * body.mass), hit.point)
    }

  /** The shape of the pile at index `i`: every kind in turn. */
  private def shapeFor(i: Int): Shape = i % 5 match
    case 0 => Circle(0.3, 2)
    case 1 => Rectangle(0.3, 0.25, 2)
    case 2 => RegularPolygon(6, 0.3, 2)
    case 3 => Capsule(0.35, 0.18, 2)
    case _ => HullPolygon(Seq(Vector2D(-0.35, -0.25), Vector2D(0.35, -0.25), Vector2D(0.1, 0.3)), 2)

  def build(): Staged =
    val world = new World:
      override def postStep(): Unit = push(this)
    Scene.container(7, 6, 4).foreach(world += _)
    val emitter = Circle(0.2, 1)
    emitter.pos = Emitter
    emitter.collidable = false
    val housing = emitter.asBody
    housing.fixed = true
    world += housing
    for i <- 0 until 30 do
      val shape = shapeFor(i)
      shape.pos = Vector2D(-4.5 + 0.9 * (i % 10) + 0.1 * (i / 10), 0.4 + 0.8 * (i / 10))
      shape.rotation = 0.3 * (i % 4)
      world += shape.asBody
    Staged(world,
      overlay = () =>
        Overlay(lines = beam(world).map(_._1), highlighted = highlighted(world), boxes = Seq(zone(world.time))))
