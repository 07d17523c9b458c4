package sims.scenes

import sims.geometry.Vector2D

/** `chain-N`, a benchmark scene: N circles of radius 0.05 on the x axis from the origin,
  * 0.2 m apart, joined by distance joints between neighbouring centres; the first is fixed,
  * links never collide, and the chain swings down. Laid out as Box2D v3's reference program
  * lays it out (`chain-N` in `shared/peers/box2d-v3/scenes.c`).
  */
final case class SwingingChain(links: Int) extends LayoutScene:
  import SwingingChain.*
  require(links > 1, s"a chain needs two links at least, got $links")

  /** Length of the chain at rest, m. */
  val length: Double = (links - 1) * Pitch

  def name: String = s"chain-$links"
  def description: String = s"$links circles joined by distance joints, the first fixed, swinging down."
  def view: Region = Region(-1.1 * length, -1.1 * length, 1.1 * length, 0.2 * length)

  lazy val layout: Layout =
    val circles = for i <- 0 until links yield SceneBody.circle(Vector2D(i * Pitch, 0), Radius, fixed = i == 0, noCollideGroup = 1)
    Layout(circles, (1 until links).map(i => SceneJoint(i - 1, i)), Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-1.5 * length, -1.5 * length, 1.5 * length, 1.5 * length))

object SwingingChain:
  /** Link radius, m. */
  val Radius: Double = 0.05
  /** Distance of neighbouring links' centres, m. */
  val Pitch: Double = 0.2
