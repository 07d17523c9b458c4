package sims.scenes

import sims.dynamics.{Body, Capsule, HullPolygon, Shape, World}
import sims.dynamics.joints.{JointLimits, JointMotor, JointSpring, RevoluteJoint}
import sims.geometry.Vector2D

/** Box2D v3's benchmark ragdoll (its "human"), 1.5 m tall and standing with its feet at
  * `position`: eleven capsule bones (hip, torso, head, two upper and lower legs, two upper and
  * lower arms) on revolute joints with Box2D's limits, each with a spring back to its rest angle
  * (`hertz`, `dampingRatio`) and joint friction (a motor holding speed 0 with at most the bone's
  * share of `frictionTorque`). Its shapes share the negative `group` (they never collide with
  * each other, nor with another human's of the same group) and are in category 2; the feet,
  * hulls at the lower legs' ends (Box2D rounds their corners by 1.5 cm; these are not rounded),
  * collide only with category 1, the ground. Needs the soft step (motors and springs).
  */
final class Human(position: Vector2D, group: Int, frictionTorque: Double = Human.FrictionTorque,
    hertz: Double = Human.Hertz, dampingRatio: Double = Human.DampingRatio):
  import Human.*
  require(group > 0, s"group must be positive, got $group")

  /** The bones, in the order of `Human.Bones`. */
  val bones: IndexedSeq[Body] = Bones.map(bone)

  /** The joints: each bone but the hip to its parent, in the bones' order. */
  val joints: IndexedSeq[RevoluteJoint] = Bones.indices.filter(Bones(_).parent >= 0).map(joint)

  /** Adds the bones and joints to `world`. */
  def addTo(world: World): Unit =
    bones.foreach(world += _)
    joints.foreach(world += _)

  /** Takes the bones and joints out of `world`. */
  def removeFrom(world: World): Unit =
    joints.foreach(world -= _)
    bones.foreach(world -= _)

  private def bone(spec: Bone): Body =
    val capsule = Capsule((spec.top - spec.bottom) / 2, spec.radius)
    capsule.pos = position + Vector2D(0, spec.y + (spec.top + spec.bottom) / 2)
    capsule.rotation = math.Pi / 2
    filter(capsule, Friction, mask = 3)
    val shapes =
      if !spec.foot then Seq(capsule)
      else
        val foot = HullPolygon(FootCorners.map(c => position + Vector2D(0, spec.y) + c))
        filter(foot, FootFriction, mask = 1)
        Seq(capsule, foot)
    val body = Body(shapes*)
    body.linearDamping = spec.linearDamping
    body

  private def filter(shape: Shape, friction: Double, mask: Int): Unit =
    shape.friction = friction
    shape.groupIndex = -group
    shape.categoryBits = 2
    shape.maskBits = mask

  private def joint(index: Int): RevoluteJoint =
    val spec = Bones(index)
    val child = bones(index)
    val pivot = position + Vector2D(0, spec.pivot)
    // Box2D turns the elbow's frame on the upper arm by `frameTurn`: its angle is measured from
    // that turn, so the arm starts bent outside the limits and its spring pulls it in. Made
    // with the child turned so about the pin, the joint's reference angle is that turn.
    if spec.frameTurn != 0 then turnAbout(child, pivot, spec.frameTurn)
    val joint = RevoluteJoint(bones(spec.parent), child, pivot)
    if spec.frameTurn != 0 then turnAbout(child, pivot, -spec.frameTurn)
    joint.limits = Some(JointLimits(spec.lower * math.Pi, spec.upper * math.Pi))
    joint.motor = Some(JointMotor(0, spec.frictionScale * frictionTorque))
    if hertz > 0 then joint.spring = Some(JointSpring(hertz, dampingRatio))
    joint

  private def turnAbout(body: Body, pivot: Vector2D, angle: Double): Unit =
    body.pos = pivot + (body.pos - pivot).rotate(angle)
    body.rotation += angle

/** The human's bones as Box2D builds them, and its defaults. */
object Human:
  /** One bone: its parent's index (-1 for the hip), body origin height above the feet, the
    * capsule's segment ends (relative to the origin) and radius, joint friction scale, linear
    * damping, the pin's height, the limits (in units of pi), a foot, and the elbow's frame turn.
    */
  final case class Bone(name: String, parent: Int, y: Double, bottom: Double, top: Double, radius: Double,
      frictionScale: Double, linearDamping: Double, pivot: Double, lower: Double, upper: Double,
      foot: Boolean = false, frameTurn: Double = 0)

  /** Box2D's eleven bones, in its order. */
  val Bones: IndexedSeq[Bone] =
    val upperLeg = Bone("upper leg", 0, 0.775, -0.125, 0.125, 0.06, 1.0, 0, 0.9, -0.05, 0.4)
    val upperArm = Bone("upper arm", 1, 1.225, -0.125, 0.125, 0.035, 0.5, 0, 1.35, -0.1, 0.8)
    IndexedSeq(
      Bone("hip", -1, 0.95, -0.02, 0.02, 0.095, 1.0, 0, 0, 0, 0),
      Bone("torso", 0, 1.2, -0.135, 0.135, 0.09, 0.5, 0, 1.0, -0.25, 0),
      Bone("head", 1, 1.475, -0.038, 0.039, 0.075, 0.25, 0.1, 1.4, -0.3, 0.1),
      upperLeg.copy(name = "upper left leg"),
      Bone("lower left leg", 3, 0.475, -0.155, 0.125, 0.045, 0.5, 0, 0.625, -0.5, -0.02, foot = true),
      upperLeg.copy(name = "upper right leg"),
      Bone("lower right leg", 5, 0.475, -0.155, 0.125, 0.045, 0.5, 0, 0.625, -0.5, -0.02, foot = true),
      upperArm.copy(name = "upper left arm"),
      Bone("lower left arm", 7, 0.975, -0.125, 0.125, 0.03, 0.1, 0.1, 1.1, -0.2, 0.3, frameTurn = 0.25 * math.Pi),
      upperArm.copy(name = "upper right arm"),
      Bone("lower right arm", 9, 0.975, -0.125, 0.125, 0.03, 0.1, 0.1, 1.1, -0.2, 0.3, frameTurn = 0.25 * math.Pi))

  /** The foot's corners relative to the lower leg's origin, m. */
  val FootCorners: Seq[Vector2D] = Seq(Vector2D(-0.03, -0.185), Vector2D(0.11, -0.185), Vector2D(0.11, -0.16),
    Vector2D(-0.03, -0.14))

  /** Friction of the bones' and of the feet's shapes. */
  val Friction: Double = 0.2
  val FootFriction: Double = 0.05
  /** The rain benchmark's joint friction torque (N m), spring frequency (Hz) and damping ratio. */
  val FrictionTorque: Double = 0.05
  val Hertz: Double = 5
  val DampingRatio: Double = 0.5
