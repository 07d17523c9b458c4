package sims.bench

import org.jbox2d.collision.shapes.{CircleShape, PolygonShape, Shape as BoxShape}
import org.jbox2d.common.Vec2
import org.jbox2d.dynamics.{Body, BodyDef, BodyType, FixtureDef, World}
import org.jbox2d.dynamics.joints.DistanceJointDef

/** The benchmark scenes in jBox2D (single precision, as the library is). */
object JBox2DScenes:
  private final class Built(val world: World, val dynamic: IndexedSeq[Body]) extends EngineScene:
    private val dt = Scenes.TimeStep.toFloat
    def step(): Unit = world.step(dt, Scenes.Iterations, Scenes.Iterations)
    def dynamicStates: Array[Double] =
      dynamic.flatMap(b => Seq(b.getPosition.x.toDouble, b.getPosition.y.toDouble, b.getAngle.toDouble)).toArray
    def jointLengths: Array[Double] =
      val out = Array.newBuilder[Double]
      var j = world.getJointList
      while j != null do
        val a = j.getBodyA.getPosition
        val b = j.getBodyB.getPosition
        out += math.hypot((b.x - a.x).toDouble, (b.y - a.y).toDouble)
        j = j.getNext
      out.result().reverse // jBox2D lists joints newest first

  private def body(world: World, kind: BodyType, x: Double, y: Double, shape: BoxShape,
      collide: Boolean = true): Body =
    val definition = BodyDef()
    definition.`type` = kind
    definition.position.set(x.toFloat, y.toFloat)
    val b = world.createBody(definition)
    val fixture = FixtureDef()
    fixture.shape = shape
    fixture.density = Scenes.Density.toFloat
    fixture.friction = Scenes.Friction.toFloat
    fixture.restitution = Scenes.Restitution.toFloat
    if !collide then fixture.filter.groupIndex = -1
    b.createFixture(fixture)
    b

  private def box(halfWidth: Double, halfHeight: Double): PolygonShape =
    val p = PolygonShape()
    p.setAsBox(halfWidth.toFloat, halfHeight.toFloat)
    p

  private def circle(radius: Double): CircleShape =
    val c = CircleShape()
    c.m_radius = radius.toFloat
    c

  private def staticBox(world: World, s: Scenes.StaticBox): Body =
    body(world, BodyType.STATIC, s.x, s.y, box(s.halfWidth, s.halfHeight))

  /** Builds the named scene. */
  def build(scene: String): EngineScene =
    val world = World(Vec2(0, Scenes.Gravity.toFloat))
    world.setAllowSleep(false)
    world.setContinuousPhysics(false)
    val dynamic = scene match
      case "pyramid-20" =>
        staticBox(world, Scenes.Pyramid.ground)
        val c = Scenes.Pyramid.centres
        for i <- 0 until c.length / 2 yield
          body(world, BodyType.DYNAMIC, c(2 * i), c(2 * i + 1), box(Scenes.Pyramid.HalfSide, Scenes.Pyramid.HalfSide))
      case "chain-100" =>
        val links = for i <- 0 until Scenes.Chain.Links yield
          body(world, if i == 0 then BodyType.STATIC else BodyType.DYNAMIC, Scenes.Chain.x(i), Scenes.Chain.y,
            circle(Scenes.Chain.Radius), collide = false)
        for i <- 1 until links.length do
          val joint = DistanceJointDef()
          joint.initialize(links(i - 1), links(i), links(i - 1).getPosition, links(i).getPosition)
          joint.collideConnected = false
          world.createJoint(joint)
        links.tail
      case other =>
        val n = Scenes.ballpitSize(other).getOrElse(throw IllegalArgumentException(s"$other is not a jBox2D scene"))
        Scenes.Ballpit.container(n).foreach(staticBox(world, _))
        val c = Scenes.Ballpit.centres(n)
        for i <- 0 until n yield
          body(world, BodyType.DYNAMIC, c(2 * i), c(2 * i + 1), circle(Scenes.Ballpit.Radius))
    Built(world, dynamic)
