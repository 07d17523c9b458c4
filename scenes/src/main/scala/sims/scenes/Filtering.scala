package sims.scenes

import sims.dynamics.{Capsule, Shape}
import sims.dynamics.joints.RevoluteJoint
import sims.geometry.Vector2D

/** Collision filtering: balls and boxes of two categories that do not collide with each other
  * roll and slide through each other; three capsules of one negative group, dropped across
  * each other onto a shelf, lie there overlapping; an arm hinged to a fixed post swings through it (its joint's
  * `collideConnected` is false).
  */
object Filtering extends Scene:
  /** The balls' collision category. */
  val BallCategory: Int = 2
  /** The boxes' collision category. */
  val BoxCategory: Int = 4
  /** The group of the crossed capsules: negative, so they never collide with each other. */
  val CapsuleGroup: Int = -1
  private val Speed = 5.0

  def name: String = "Filtering"
  def description: String =
    "Balls and boxes of two categories pass through each other; capsules of a negative group overlap; a hinged arm swings through its post."
  def view: Region = Region(-9, -1, 9, 7)
  override def region: Region = Region(-8, -0.2, 8, 7)

  /** Puts `shape` in `category`, colliding with everything but `other`. */
  private def only(shape: Shape, category: Int, other: Int): Unit =
    shape.categoryBits = category
    shape.maskBits = ~other

  def build(): Staged =
    val world = Scene.worldOf(Scene.container(9, 8, 3)*)
    for i <- 0 until 10 do
      val ball = Scene.ball(Vector2D(-7.2 + 0.65 * (i % 5), 0.31 + 0.65 * (i / 5)), 0.3)
      only(ball.shapes.head, BallCategory, BoxCategory)
      ball.linearVelocity = Vector2D(Speed, 0)
      world += ball
      val box = Scene.box(Vector2D(7.2 - 0.65 * (i % 5), 0.31 + 0.65 * (i / 5)), 0.3, 0.3)
      only(box.shapes.head, BoxCategory, BallCategory)
      box.linearVelocity = Vector2D(-Speed, 0)
      world += box
    // Three capsules crossing at one point on a shelf out of the others' way, each its own
    // body: their group keeps them from pushing each other apart.
    world += Scene.fixedBox(Vector2D(-4, 3.2), 1.5, 0.1)
    for k <- 0 until 3 do
      val capsule = Capsule(0.8, 0.15, 1)
      capsule.pos = Vector2D(-4, 3.8)
      capsule.rotation = k * math.Pi / 3
      capsule.groupIndex = CapsuleGroup
      world += capsule.asBody
    // A post and an arm hinged to it, overlapping at the hinge.
    val post = Scene.fixedBox(Vector2D(3, 4.5), 0.15, 0.6)
    val arm = Scene.box(Vector2D(3.9, 4.8), 0.9, 0.1)
    world += post
    world += arm
    val hinge = RevoluteJoint(post, arm, Vector2D(3, 4.8))
    hinge.collideConnected = false
    world += hinge
    Staged(world)
