package sims.scenes

import sims.dynamics.{Body, Circle, Shape, World}
import sims.geometry.Vector2D

/** Bullets: two cannons fire balls of 0.2 m at 100 m/s at two walls 5 cm thick, every half
  * second. The upper cannon's balls are ordinary bodies: under the classic step they cross the
  * wall between two steps and land behind it; the soft step's speculative contacts stop most of
  * them, not those set spinning fast by the others. The lower cannon's are bullets
  * (`Body.bullet`): the continuous collision stage stops each at the wall, and it bounces back,
  * under either step. Thick walls and a backstop keep every ball in the room.
  */
object Bullet extends Scene:
  /** Where the upper (ordinary) and the lower (bullet) cannon fire from, m. */
  val UpperMuzzle: Vector2D = Vector2D(-9, 4.5)
  val LowerMuzzle: Vector2D = Vector2D(-9, 1.5)
  /** Muzzle speed, m/s. */
  val Speed: Double = 100
  /** The thin walls' x (their centre) and half thickness, m. */
  val WallX: Double = 4
  val WallHalfThickness: Double = 0.025
  /** Shots per cannon, one every `Interval` steps. */
  val Shots: Int = 6
  val Interval: Int = 30
  private val Radius = 0.1

  def name: String = "Bullet"
  def description: String =
    "Cannons fire balls at 100 m/s at two 5 cm walls: the ordinary balls cross the upper one under the classic step, the bullets never."
  def view: Region = Region(-10.5, -0.8, 10.5, 7.5)
  // The room is x from -10 to 9.5 and y from 0 to 7; a ball that crossed a thin wall is in the
  // backstop (up to one step's flight, 1.7 m) for the step before it is pushed back out.
  override def region: Region = Region(-10.5, -0.2, 12, 7.2)

  /** A world whose cannons fire on their own. */
  final class CannonWorld extends World:
    /** The balls fired so far by the upper cannon (ordinary) and the lower one (bullets). */
    val ordinary, bullets = scala.collection.mutable.ArrayBuffer.empty[Body]
    private var steps = 0

    override def postStep(): Unit =
      steps += 1
      if steps % Interval == 1 && bullets.size < Shots then fire()

    /** Fires one ball from each cannon. */
    def fire(): Unit =
      ordinary += shot(UpperMuzzle, bullet = false)
      bullets += shot(LowerMuzzle, bullet = true)

    private def shot(muzzle: Vector2D, bullet: Boolean): Body =
      val ball = Circle(Radius, 4)
      ball.pos = muzzle
      val body = ball.asBody
      body.linearVelocity = Vector2D(Speed, 0)
      body.bullet = bullet
      this += body
      body

  /** The balls of `balls` beyond the wall (crossed it). */
  def crossed(balls: Iterable[Body]): Int = balls.count(_.pos.x > WallX)

  def build(): Staged =
    val world = CannonWorld()
    // A room of thick walls: a ball bouncing back at 50 m/s moves 0.8 m in a step, and the
    // classic step pushes an overlap out on the near side only while it is less than half the
    // wall; the backstop behind the thin walls catches what crosses them at 100 m/s.
    world += Scene.fixedBox(Vector2D(0, -1), 12, 1) // floor
    world += Scene.fixedBox(Vector2D(0, 8), 12, 1) // ceiling
    world += Scene.fixedBox(Vector2D(-11.5, 3.5), 1.5, 4.5) // left wall, behind the cannons
    world += Scene.fixedBox(Vector2D(12, 3.5), 2.5, 4.5) // backstop
    // A shelf between the two lanes, and the two thin walls, one across each lane from floor
    // to shelf and from shelf to ceiling: nothing passes them but through them.
    world += Scene.fixedBox(Vector2D(-2.5, 3), 7, 0.05)
    world += Scene.fixedBox(Vector2D(WallX, 5), WallHalfThickness, 2)
    world += Scene.fixedBox(Vector2D(WallX, 1.5), WallHalfThickness, 1.5)
    world.fire()
    Staged(world, overlay = () => overlay(world))

  /** The bullets highlighted, and per lane how many balls crossed its wall. */
  def overlay(world: CannonWorld): Overlay =
    Overlay(highlighted = world.bullets.iterator.flatMap(_.shapes).toSet,
      labels = Seq(
        Vector2D(-9, 5.6) -> s"ordinary balls: ${crossed(world.ordinary)} of ${world.ordinary.size} through",
        Vector2D(-9, 2.6) -> s"bullets: ${crossed(world.bullets)} of ${world.bullets.size} through"))
