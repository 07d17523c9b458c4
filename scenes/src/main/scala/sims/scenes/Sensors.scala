package sims.scenes

import scala.collection.mutable
import sims.dynamics.{Circle, Rectangle, Shape, World}
import sims.geometry.Vector2D

/** Sensor shapes and their events: balls dropped one by one into a container bounce off a
  * bumper and roll about its floor; a zone on the right of the floor is a fixed sensor box. The
  * zone never pushes a ball; it counts the balls inside it from its begin and end events
  * (`World.sensorEvents`), and the balls inside are highlighted from the step they come in to
  * the step they leave, the zone too while any is inside.
  */
object Sensors extends Scene:
  /** The zone's centre, m. */
  val ZoneCentre: Vector2D = Vector2D(2.75, 0.75)
  /** The zone's half width and half height, m. */
  val ZoneHalfWidth: Double = 2.25
  val ZoneHalfHeight: Double = 0.75
  /** Balls dropped, one every `DropInterval` steps. */
  val Balls: Int = 24
  val DropInterval: Int = 12
  private val Radius = 0.2

  def name: String = "Sensors"
  def description: String = "A sensor zone counts the balls inside it from its begin and end events; they pass through it."
  def view: Region = Region(-6.5, -0.8, 6.5, 7)
  override def region: Region = Region(-5.5, -0.2, 5.5, 7)

  /** A world with the scene's zone, and the balls inside it as its events tell. */
  final class SensorWorld extends World:
    /** The zone: a fixed sensor box on the right of the floor. */
    val zone: Rectangle = Rectangle(ZoneHalfWidth, ZoneHalfHeight, 1)
    /** The balls inside the zone, in the order they came in: kept from its begins and ends. */
    val inside: mutable.LinkedHashSet[Shape] = mutable.LinkedHashSet.empty
    /** How many balls have come into the zone so far. */
    var entered: Int = 0
    private var steps = 0
    private var dropped = 0

    override def postStep(): Unit =
      for b <- sensorEvents.begins if b.sensor eq zone do
        inside += b.visitor
        entered += 1
      for e <- sensorEvents.ends if e.sensor eq zone do inside -= e.visitor
      steps += 1
      if steps % DropInterval == 0 && dropped < Balls then drop()

    /** Drops the next ball from above the container, a little left or right of the bumper. */
    private def drop(): Unit =
      val ball = Circle(Radius, 1)
      ball.pos = Vector2D(-1.6 + 0.4 * ((dropped * 7) % 9) / 4.0, 6.2)
      ball.restitution = 0.5
      this += ball.asBody
      dropped += 1

  def build(): Staged =
    val world = SensorWorld()
    Scene.container(5.5, 5, 4).foreach(world += _)
    // A bumper under the drop, sloping down to the right: most balls bounce off it towards the zone.
    world += Scene.fixedBox(Vector2D(-1.2, 2.5), 0.6, 0.1, -0.35)
    world.zone.pos = ZoneCentre
    world.zone.sensor = true
    val zoneBody = world.zone.asBody
    zoneBody.fixed = true
    world += zoneBody
    Staged(world, overlay = () => overlay(world))

  /** The highlighted balls inside the zone (and the zone while any is), and the counts. */
  def overlay(world: SensorWorld): Overlay =
    val shown: Set[Shape] = world.inside.toSet ++ (if world.inside.nonEmpty then Set(world.zone) else Set.empty)
    Overlay(highlighted = shown,
      labels = Seq(Vector2D(ZoneCentre.x - ZoneHalfWidth + 0.15, ZoneCentre.y + ZoneHalfHeight + 0.2) ->
        s"inside: ${world.inside.size}  entered: ${world.entered}"))
