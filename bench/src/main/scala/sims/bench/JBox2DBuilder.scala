package sims.bench

import org.jbox2d.collision.shapes.{CircleShape, PolygonShape, Shape as JShape}
import org.jbox2d.common.Vec2
import org.jbox2d.dynamics.{Body, BodyDef, BodyType, FixtureDef, World}
import org.jbox2d.dynamics.joints.{DistanceJoint, DistanceJointDef, RevoluteJoint, RevoluteJointDef}
import sims.scenes.{JointKind, Layout, Outline}

/** Builds a layout in jBox2D (single precision, as the library is): body for body and joint
  * for joint, with the bench's iterations and the peers' settings.
  */
object JBox2DBuilder:
  private final class Built(val world: World, val dynamic: IndexedSeq[Body], timeStep: Double) extends EngineScene:
    private val dt = timeStep.toFloat
    def step(): Unit = world.step(dt, Settings.Iterations, Settings.Iterations)
    def dynamicStates: Array[Double] =
      dynamic.flatMap(b => Seq(b.getPosition.x.toDouble, b.getPosition.y.toDouble, b.getAngle.toDouble)).toArray
    def dynamicVelocities: Array[Double] =
      dynamic.flatMap { b =>
        val v = b.getLinearVelocity
        Seq(v.x.toDouble, v.y.toDouble, b.getAngularVelocity.toDouble)
      }.toArray
    def jointLengths: Array[Double] =
      val out = Array.newBuilder[Double]
      var j = world.getJointList
      while j != null do
        if j.isInstanceOf[DistanceJoint] then
          val a = j.getBodyA.getPosition
          val b = j.getBodyB.getPosition
          out += math.hypot((b.x - a.x).toDouble, (b.y - a.y).toDouble)
        j = j.getNext
      out.result().reverse // jBox2D lists joints newest first
    def pinGaps: Array[Double] =
      val out = Array.newBuilder[Double]
      val (a, b) = (Vec2(), Vec2())
      var j = world.getJointList
      while j != null do
        if j.isInstanceOf[RevoluteJoint] then
          j.getAnchorA(a)
          j.getAnchorB(b)
          out += math.hypot((b.x - a.x).toDouble, (b.y - a.y).toDouble)
        j = j.getNext
      out.result().reverse

  private def shape(outline: Outline): JShape = outline match
    case Outline.Circle(radius) =>
      val c = CircleShape()
      c.m_radius = radius.toFloat
      c
    case Outline.Box(halfWidth, halfHeight) =>
      val p = PolygonShape()
      p.setAsBox(halfWidth.toFloat, halfHeight.toFloat)
      p

  /** Builds the layout. */
  def build(layout: Layout): EngineScene =
    val world = World(Vec2(layout.gravity.x.toFloat, layout.gravity.y.toFloat))
    world.setAllowSleep(false)
    world.setContinuousPhysics(false)
    val bodies =
      for spec <- layout.bodies yield
        val definition = BodyDef()
        definition.`type` = if spec.fixed then BodyType.STATIC else BodyType.DYNAMIC
        definition.position.set(spec.centre.x.toFloat, spec.centre.y.toFloat)
        definition.linearVelocity.set(spec.velocity.x.toFloat, spec.velocity.y.toFloat)
        val body = world.createBody(definition)
        val fixture = FixtureDef()
        fixture.shape = shape(spec.outline)
        fixture.density = spec.density.toFloat
        fixture.friction = spec.friction.toFloat
        fixture.restitution = spec.restitution.toFloat
        // Shapes of one negative group index never collide with each other.
        fixture.filter.groupIndex = -spec.noCollideGroup
        body.createFixture(fixture)
        body
    for joint <- layout.joints do
      joint.kind match
        case JointKind.Distance =>
          val definition = DistanceJointDef()
          definition.bodyA = bodies(joint.body1) // anchors at the body origins: the centres
          definition.bodyB = bodies(joint.body2)
          definition.length = layout.length(joint).toFloat
          definition.collideConnected = false
          world.createJoint(definition)
        case JointKind.Revolute =>
          val definition = RevoluteJointDef()
          val pin = layout.pin(joint)
          definition.initialize(bodies(joint.body1), bodies(joint.body2), Vec2(pin.x.toFloat, pin.y.toFloat))
          definition.collideConnected = false
          world.createJoint(definition)
    Built(world, layout.freeBodies.map(bodies), layout.timeStep)
