package sims.bench

import org.dyn4j.collision.CategoryFilter
import org.dyn4j.dynamics.{Body, ContinuousDetectionMode}
import org.dyn4j.dynamics.joint.DistanceJoint
import org.dyn4j.geometry.{Convex, Geometry, MassType}
import org.dyn4j.world.World

/** The benchmark scenes in dyn4j. */
object Dyn4jScenes:
  private final class Built(val world: World[Body], val dynamic: IndexedSeq[Body]) extends EngineScene:
    def step(): Unit = world.step(1)
    def dynamicStates: Array[Double] =
      dynamic.flatMap { b =>
        val t = b.getTransform
        Seq(t.getTranslationX, t.getTranslationY, t.getRotationAngle)
      }.toArray
    def jointLengths: Array[Double] =
      val out = Array.newBuilder[Double]
      world.getJoints.forEach {
        case j: DistanceJoint[?] => out += j.getAnchor1.distance(j.getAnchor2)
        case _ => ()
      }
      out.result()

  private def body(world: World[Body], fixed: Boolean, x: Double, y: Double, shape: Convex,
      collide: Boolean = true): Body =
    val b = Body()
    val fixture = b.addFixture(shape, Scenes.Density, Scenes.Friction, Scenes.Restitution)
    if !collide then fixture.setFilter(CategoryFilter(1, 0)) // no category accepts it
    b.setMass(if fixed then MassType.INFINITE else MassType.NORMAL)
    b.translate(x, y)
    world.addBody(b)
    b

  private def staticBox(world: World[Body], s: Scenes.StaticBox): Body =
    body(world, true, s.x, s.y, Geometry.createRectangle(2 * s.halfWidth, 2 * s.halfHeight))

  /** Builds the named scene. */
  def build(scene: String): EngineScene =
    val world = World[Body]()
    world.setGravity(0, Scenes.Gravity)
    val settings = world.getSettings
    settings.setStepFrequency(Scenes.TimeStep)
    settings.setVelocityConstraintSolverIterations(Scenes.Iterations)
    settings.setPositionConstraintSolverIterations(Scenes.Iterations)
    settings.setAtRestDetectionEnabled(false)
    settings.setContinuousDetectionMode(ContinuousDetectionMode.NONE)
    val dynamic = scene match
      case "pyramid-20" =>
        staticBox(world, Scenes.Pyramid.ground)
        val c = Scenes.Pyramid.centres
        val side = 2 * Scenes.Pyramid.HalfSide
        for i <- 0 until c.length / 2 yield
          body(world, false, c(2 * i), c(2 * i + 1), Geometry.createRectangle(side, side))
      case "chain-100" =>
        val links = for i <- 0 until Scenes.Chain.Links yield
          body(world, i == 0, Scenes.Chain.x(i), Scenes.Chain.y, Geometry.createCircle(Scenes.Chain.Radius),
            collide = false)
        for i <- 1 until links.length do
          val a = links(i - 1)
          val b = links(i)
          world.addJoint(DistanceJoint[Body](a, b, a.getWorldCenter, b.getWorldCenter))
        links.tail
      case other =>
        val n = Scenes.ballpitSize(other).getOrElse(throw IllegalArgumentException(s"$other is not a dyn4j scene"))
        Scenes.Ballpit.container(n).foreach(staticBox(world, _))
        val c = Scenes.Ballpit.centres(n)
        for i <- 0 until n yield
          body(world, false, c(2 * i), c(2 * i + 1), Geometry.createCircle(Scenes.Ballpit.Radius))
    Built(world, dynamic)
