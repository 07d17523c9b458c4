package sims.collision

import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D

/** Small scenes shared by the collision tests. */
object Scenes:
  /** A fixed ground box whose top face is at y = 0. */
  def ground(halfWidth: Double = 10): Body =
    val r = Rectangle(halfWidth, 0.5, 1)
    r.pos = Vector2D(0, -0.5)
    val b = r.asBody
    b.fixed = true
    b

  /** A ball of radius r whose lowest point is at `height`. */
  def ball(radius: Double, x: Double, height: Double): Body =
    val c = Circle(radius, 1)
    c.pos = Vector2D(x, height + radius)
    c.asBody

  /** A world with a fixed ground (top face at y = 0, `halfWidth` wide each side) and two
    * fixed walls 0.5 m thick and `height` high whose inner faces are `inner` from the middle.
    */
  def container(halfWidth: Double, inner: Double, height: Double): World =
    val world = World()
    world += ground(halfWidth)
    for x <- Seq(-(inner + 0.25), inner + 0.25) do
      val wall = Rectangle(0.25, height / 2, 1)
      wall.pos = Vector2D(x, height / 2)
      val b = wall.asBody
      b.fixed = true
      world += b
    world

  /** The original's BallStack: a fixed ground and two walls 4 m apart inside, and balls
    * poured in rows above them (the walls reach 4 m up).
    */
  def ballStack(balls: Int): (World, Seq[Body]) =
    val world = container(halfWidth = 3, inner = 2, height = 4)
    val bodies = for i <- 0 until balls yield
      val b = ball(0.15, -1.6 + (i % 9) * 0.4 + (i / 9 % 2) * 0.1, 0.3 + (i / 9) * 0.45)
      world += b
      b
    (world, bodies)
