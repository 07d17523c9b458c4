package sims.bench

import sims.dynamics.{Body, Circle, Rectangle, Shape, World}
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

/** The benchmark scenes in SiMS. */
object SimsScenes:
  // The contact uses the product of the two shapes' values: sqrt(0.5)^2 = 0.5.
  private val ShapeFriction = math.sqrt(Scenes.Friction)

  private final class Built(val world: World, val dynamic: IndexedSeq[Body]) extends EngineScene:
    def step(): Unit = world.step()
    def dynamicStates: Array[Double] =
      dynamic.flatMap(b => Seq(b.pos.x, b.pos.y, b.rotation)).toArray
    def jointLengths: Array[Double] =
      world.joints.collect { case j: DistanceJoint => (j.connection2 - j.connection1).length }.toArray

  /** A world with the benchmark settings. */
  def newWorld(): World =
    val world = World()
    world.timeStep = Scenes.TimeStep
    world.iterations = Scenes.Iterations
    world.gravity = Vector2D(0, Scenes.Gravity)
    world

  private def material(s: Shape): s.type =
    s.friction = ShapeFriction
    s.restitution = Scenes.Restitution
    s

  private def staticBox(b: Scenes.StaticBox): Body =
    val r = material(Rectangle(b.halfWidth, b.halfHeight, Scenes.Density))
    r.pos = Vector2D(b.x, b.y)
    val body = r.asBody
    body.fixed = true
    body

  private def ball(x: Double, y: Double, radius: Double): Body =
    val c = material(Circle(radius, Scenes.Density))
    c.pos = Vector2D(x, y)
    c.asBody

  /** The world of the named scene (for tools that look inside a SiMS step). */
  def buildWorld(scene: String): World = build(scene).asInstanceOf[Built].world

  /** Builds the named scene. */
  def build(scene: String): EngineScene =
    val world = newWorld()
    val dynamic = scene match
      case "pyramid-20" =>
        world += staticBox(Scenes.Pyramid.ground)
        val c = Scenes.Pyramid.centres
        for i <- 0 until c.length / 2 yield
          val r = material(Rectangle(Scenes.Pyramid.HalfSide, Scenes.Pyramid.HalfSide, Scenes.Density))
          r.pos = Vector2D(c(2 * i), c(2 * i + 1))
          val b = r.asBody
          world += b
          b
      case "chain-100" =>
        val links = for i <- 0 until Scenes.Chain.Links yield
          val b = ball(Scenes.Chain.x(i), Scenes.Chain.y, Scenes.Chain.Radius)
          b.shapes.foreach(_.collidable = false)
          world += b
          b
        links.head.fixed = true
        for i <- 1 until links.length do
          world += DistanceJoint(links(i - 1), links(i - 1).pos, links(i), links(i).pos)
        links.tail
      case "ballstack" =>
        val stack = sims.scenes.BallStack.build().world
        return Built(stack, stack.bodies.filterNot(_.fixed).toIndexedSeq)
      case other =>
        val n = Scenes.ballpitSize(other).getOrElse(throw IllegalArgumentException(s"unknown scene $other"))
        Scenes.Ballpit.container(n).foreach(s => world += staticBox(s))
        val c = Scenes.Ballpit.centres(n)
        for i <- 0 until n yield
          val b = ball(c(2 * i), c(2 * i + 1), Scenes.Ballpit.Radius)
          world += b
          b
    Built(world, dynamic)
