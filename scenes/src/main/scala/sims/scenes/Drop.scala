package sims.scenes

import sims.geometry.Vector2D

/** `drop-eE`, a quality scene of restitution: a ball of radius 0.25 m dropped from 1 m (its
  * lowest point 1 m above the ground's top face) onto a fixed ground, the pair's restitution
  * E (0 to 1): a perfect bounce rises to E^2 of the drop, then E^4, ...
  *
  * The pair's value is E in every engine: both shapes are given E. The peers give a pair the
  * larger of its two values (max(E, E) = E); SiMS multiplies them, and [[Layout.world]] gives
  * its shapes the square roots (sqrt(E) sqrt(E) = E).
  */
final case class Drop(restitution: Double) extends LayoutScene:
  require(restitution >= 0 && restitution <= 1, s"restitution $restitution is not in [0, 1]")

  def name: String = s"drop-e${Drop.format(restitution)}"
  def description: String = s"A ball dropped 1 m onto the ground, restitution ${Drop.format(restitution)} for the pair."
  def view: Region = Region(-1.5, -0.5, 1.5, Drop.Height + 2 * Drop.Radius + 0.25)

  lazy val layout: Layout =
    val ground = SceneBody(Outline.Box(Drop.GroundHalfWidth, 0.5), Vector2D(0, -0.5), fixed = true, 0,
      Layout.StandardFriction, restitution)
    val ball = SceneBody(Outline.Circle(Drop.Radius), Vector2D(0, Drop.Height + Drop.Radius), fixed = false, 1,
      Layout.StandardFriction, restitution)
    Layout(IndexedSeq(ground, ball), IndexedSeq.empty, Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-Drop.GroundHalfWidth, 0, Drop.GroundHalfWidth, Drop.Height + 2 * Drop.Radius + 0.5))

object Drop:
  /** The drop: height of the ball's lowest point above the ground's top face at the start, m. */
  val Height: Double = 1.0
  /** Radius of the ball, m. */
  val Radius: Double = 0.25
  /** Half the width of the ground box, m. */
  val GroundHalfWidth: Double = 2.0

  /** The restitutions of the quality report's drops. */
  val Restitutions: Seq[Double] = Seq(1, 0.5, 0)

  /** A restitution as scene names write it: 1, 0.5, 0. */
  def format(restitution: Double): String =
    if restitution == math.rint(restitution) then restitution.toLong.toString else restitution.toString
