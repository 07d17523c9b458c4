package sims.prefabs

import sims.dynamics.{Body, Circle, Rectangle, Shape}
import sims.dynamics.joints.RevoluteJoint
import sims.geometry.Vector2D

/** A human figure of 9 bodies pinned together by 8 revolute joints, standing upright, as the
  * original's ragdoll: head and torso are one body, each upper arm one, each forearm with its hand
  * one, each thigh one, each tibia with its foot one; shoulders, elbows, hips and knees are the
  * joints. The figure is about 1.7 m tall and weighs about 54 kg.
  *
  * Hands and feet are shapes of the forearms and tibias rather than bodies of their own behind a
  * wrist or ankle joint: a light foot that has to stop the whole figure on landing cannot do it
  * through a chain of joints in a few iterations, and the ankles then open by several centimetres.
  *
  * The parts of one figure never collide with each other: pinned parts overlap at the joints, and
  * in a plane the left and right limbs would jam against each other (in depth, a real body has
  * them side by side). They collide with everything else, other ragdolls included.
  *
  * @param position where the centre of the torso is placed, world coordinates
  */
final class Ragdoll(position: Vector2D) extends Prefab:
  Vector2D.requireFinite("position", position)

  import Ragdoll.*

  /** Point `(x, y)` relative to the torso's centre, in world coordinates. */
  private def at(x: Double, y: Double): Vector2D = position + Vector2D(x, y)

  private def rectangle(halfWidth: Double, halfHeight: Double, centre: Vector2D): Rectangle =
    val shape = new Rectangle(halfWidth, halfHeight, Density)
    shape.pos = centre
    shape

  private def circle(radius: Double, centre: Vector2D): Circle =
    val shape = Circle(radius, Density)
    shape.pos = centre
    shape

  /** Head and torso, one body: the head sits on top of the torso. */
  val headTorso: Body =
    Body(rectangle(TorsoHalfWidth, TorsoHalfHeight, at(0, 0)), circle(HeadRadius, at(0, TorsoHalfHeight + HeadRadius)))

  // Arms hang from the torso's sides (overlapping it: they are in front of or behind it), legs below it; side -1 is the figure's right, +1 its left.
  private val armX = TorsoHalfWidth
  private val shoulderY = TorsoHalfHeight - ArmHalfWidth
  private val elbowY = shoulderY - 2 * ArmHalfLength
  private val wristY = elbowY - 2 * ForearmHalfLength
  private val legX = TorsoHalfWidth - ThighHalfWidth - 0.01
  private val hipY = -TorsoHalfHeight
  private val kneeY = hipY - 2 * ThighHalfLength
  private val ankleY = kneeY - 2 * TibiaHalfLength

  private def arm(side: Int) = rectangle(ArmHalfWidth, ArmHalfLength, at(side * armX, shoulderY - ArmHalfLength)).asBody
  private def forearm(side: Int) =
    Body(rectangle(ForearmHalfWidth, ForearmHalfLength, at(side * armX, elbowY - ForearmHalfLength)),
      circle(HandRadius, at(side * armX, wristY - HandRadius)))
  private def thigh(side: Int) = rectangle(ThighHalfWidth, ThighHalfLength, at(side * legX, hipY - ThighHalfLength)).asBody
  // Feet point forwards (to +x), their heel under the tibia.
  private def tibia(side: Int) =
    Body(rectangle(TibiaHalfWidth, TibiaHalfLength, at(side * legX, kneeY - TibiaHalfLength)),
      rectangle(FootHalfLength, FootHalfHeight, at(side * legX + FootHalfLength - TibiaHalfWidth, ankleY - FootHalfHeight)))

  /** Upper arms: right, left. */
  val arms: Seq[Body] = Seq(arm(-1), arm(1))
  /** Forearms, each with its hand: right, left. */
  val forearms: Seq[Body] = Seq(forearm(-1), forearm(1))
  /** Thighs: right, left. */
  val thighs: Seq[Body] = Seq(thigh(-1), thigh(1))
  /** Tibias (lower legs), each with its foot: right, left. */
  val tibias: Seq[Body] = Seq(tibia(-1), tibia(1))

  private def bothSides(pin: (Int, Int) => RevoluteJoint): Seq[RevoluteJoint] = Seq(pin(-1, 0), pin(1, 1))

  /** Shoulders (torso - upper arm): right, left. */
  val shoulders: Seq[RevoluteJoint] = bothSides((side, i) => RevoluteJoint(headTorso, arms(i), at(side * armX, shoulderY)))
  /** Elbows (upper arm - forearm): right, left. */
  val elbows: Seq[RevoluteJoint] = bothSides((side, i) => RevoluteJoint(arms(i), forearms(i), at(side * armX, elbowY)))
  /** Hips (torso - thigh): right, left. */
  val hips: Seq[RevoluteJoint] = bothSides((side, i) => RevoluteJoint(headTorso, thighs(i), at(side * legX, hipY)))
  /** Knees (thigh - tibia): right, left. */
  val knees: Seq[RevoluteJoint] = bothSides((side, i) => RevoluteJoint(thighs(i), tibias(i), at(side * legX, kneeY)))

  /** All 9 parts, head and torso first. */
  val bodies: Seq[Body] = headTorso +: (arms ++ forearms ++ thighs ++ tibias)

  /** All 8 joints, from the torso outwards. */
  val joints: Seq[RevoluteJoint] = shoulders ++ elbows ++ hips ++ knees

  /** All shapes of the figure. */
  def shapes: Seq[Shape] = bodies.flatMap(_.shapes)

  // See the class comment: the figure's parts never collide with each other.
  private val figure: Set[Shape] = shapes.toSet
  for s <- figure do s.transientShapes ++= figure - s

/** Dimensions of a [[Ragdoll]], m, and its density, kg/m^2. */
object Ragdoll:
  /** Density of every part, kg/m^2 (a figure of about 54 kg). */
  val Density: Double = 100
  private val TorsoHalfWidth = 0.15
  private val TorsoHalfHeight = 0.3
  private val HeadRadius = 0.11
  private val ArmHalfWidth = 0.05
  private val ArmHalfLength = 0.15
  private val ForearmHalfWidth = 0.045
  private val ForearmHalfLength = 0.14
  private val HandRadius = 0.05
  private val ThighHalfWidth = 0.06
  private val ThighHalfLength = 0.2
  private val TibiaHalfWidth = 0.05
  private val TibiaHalfLength = 0.2
  private val FootHalfLength = 0.1
  private val FootHalfHeight = 0.03
