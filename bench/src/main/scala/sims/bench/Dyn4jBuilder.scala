package sims.bench

import org.dyn4j.collision.CategoryFilter
import org.dyn4j.dynamics.{Body, ContinuousDetectionMode}
import org.dyn4j.dynamics.joint.{DistanceJoint, RevoluteJoint}
import org.dyn4j.geometry.{Convex, Geometry, MassType, Vector2}
import org.dyn4j.world.World
import sims.scenes.{JointKind, Layout, Outline}

/** Builds a layout in dyn4j: body for body and joint for joint, with the bench's iterations
  * and the peers' settings.
  */
object Dyn4jBuilder:
  private final class Built(val world: World[Body], val dynamic: IndexedSeq[Body]) extends EngineScene:
    def step(): Unit = world.step(1)
    def dynamicStates: Array[Double] =
      dynamic.flatMap { b =>
        val t = b.getTransform
        Seq(t.getTranslationX, t.getTranslationY, t.getRotationAngle)
      }.toArray
    def dynamicVelocities: Array[Double] =
      dynamic.flatMap { b =>
        val v = b.getLinearVelocity
        Seq(v.x, v.y, b.getAngularVelocity)
      }.toArray
    def jointLengths: Array[Double] =
      val out = Array.newBuilder[Double]
      world.getJoints.forEach {
        case j: DistanceJoint[?] => out += j.getAnchor1.distance(j.getAnchor2)
        case _ => ()
      }
      out.result()
    def pinGaps: Array[Double] =
      val out = Array.newBuilder[Double]
      world.getJoints.forEach {
        case j: RevoluteJoint[?] => out += j.getAnchor1.distance(j.getAnchor2)
        case _ => ()
      }
      out.result()

  private def shape(outline: Outline): Convex = outline match
    case Outline.Circle(radius) => Geometry.createCircle(radius)
    case Outline.Box(halfWidth, halfHeight) => Geometry.createRectangle(2 * halfWidth, 2 * halfHeight)

  /** The filter of group g > 0: its own category, and a mask of every category but its own
    * (bodies of group 0 keep dyn4j's default filter, which allows every pair).
    */
  private def filter(group: Int): CategoryFilter =
    require(group < 64, s"dyn4j's categories hold groups up to 63, not $group")
    CategoryFilter(1L << group, ~(1L << group))

  /** Builds the layout. */
  def build(layout: Layout): EngineScene =
    val world = World[Body]()
    world.setGravity(layout.gravity.x, layout.gravity.y)
    val settings = world.getSettings
    settings.setStepFrequency(layout.timeStep)
    settings.setVelocityConstraintSolverIterations(Settings.Iterations)
    settings.setPositionConstraintSolverIterations(Settings.Iterations)
    settings.setAtRestDetectionEnabled(false)
    settings.setContinuousDetectionMode(ContinuousDetectionMode.NONE)
    val bodies =
      for spec <- layout.bodies yield
        val body = Body()
        val fixture = body.addFixture(shape(spec.outline), spec.density, spec.friction, spec.restitution)
        if spec.noCollideGroup > 0 then fixture.setFilter(filter(spec.noCollideGroup))
        body.setMass(if spec.fixed then MassType.INFINITE else MassType.NORMAL)
        body.translate(spec.centre.x, spec.centre.y)
        body.setLinearVelocity(spec.velocity.x, spec.velocity.y)
        world.addBody(body)
        body
    for joint <- layout.joints do
      val (a, b) = (bodies(joint.body1), bodies(joint.body2))
      joint.kind match
        case JointKind.Distance =>
          val distance = DistanceJoint[Body](a, b, a.getWorldCenter, b.getWorldCenter)
          distance.setRestDistance(layout.length(joint))
          world.addJoint(distance)
        case JointKind.Revolute =>
          val pin = layout.pin(joint)
          world.addJoint(RevoluteJoint[Body](a, b, Vector2(pin.x, pin.y)))
    Built(world, layout.freeBodies.map(bodies))
