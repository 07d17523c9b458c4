package sims.scenes

import sims.geometry.Vector2D

/** `stack-N`, a quality scene: N boxes of 0.5 m stacked straight up on a fixed ground, each
  * resting on the one below and shifted sideways by a few millimetres (box i by
  * 2 mm x ((7 i) mod 5 - 2), so no two neighbours line up exactly). A solver should keep it
  * standing: the soft step's target is the top box within 10 cm of its start and no box
  * turned by more than 0.05 rad over 30 s.
  */
final case class BoxStack(boxes: Int) extends LayoutScene:
  require(boxes > 0, s"a stack needs boxes, got $boxes")

  def name: String = s"stack-$boxes"
  def description: String = s"$boxes boxes of 0.5 m stacked straight up on the ground."
  def view: Region = BoxStack.view(boxes)

  lazy val layout: Layout = BoxStack.layout(IndexedSeq.fill(boxes)(1.0))

/** `heavy-stack`, a quality scene: three boxes of 0.5 m stacked as in [[BoxStack]], the top one
  * 100 times denser than the two below (a mass ratio of 100). The soft step's target: the top
  * box sinks by less than 3 cm in 10 s and stays upright.
  */
object HeavyStack extends LayoutScene:
  /** Density of the top box, kg/m^2 (the others have 1). */
  val TopDensity: Double = 100

  def name: String = "heavy-stack"
  def description: String = s"Three boxes of 0.5 m stacked up, the top one $TopDensity%.0f times denser."
  def view: Region = BoxStack.view(3)

  lazy val layout: Layout = BoxStack.layout(IndexedSeq(1.0, 1.0, TopDensity))

object BoxStack:
  /** Half the side of a box, m. */
  val HalfSide: Double = 0.25
  /** Half the width of the ground box, m. */
  val GroundHalfWidth: Double = 5.0
  /** Unit of the boxes' sideways shifts, m. */
  val Shift: Double = 0.002

  /** Sideways shift of box i from x = 0, m: -4, 0, 4, -2, 2, -4, ... mm. */
  def shift(i: Int): Double = Shift * ((i * 7) % 5 - 2)

  /** A fixed ground (top face at y = 0) and one box per density, bottom to top, each resting
    * on the one below; standard friction 0.5 and restitution 0.
    */
  def layout(densities: IndexedSeq[Double]): Layout =
    val ground = SceneBody.box(Vector2D(0, -0.5), GroundHalfWidth, 0.5, fixed = true)
    val boxes = densities.indices.map { i =>
      SceneBody(Outline.Box(HalfSide, HalfSide), Vector2D(shift(i), HalfSide + 2 * HalfSide * i), fixed = false,
        densities(i), Layout.StandardFriction, 0)
    }
    Layout(ground +: boxes, IndexedSeq.empty, Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-GroundHalfWidth, 0, GroundHalfWidth, 2 * HalfSide * densities.size + 1))

  /** A camera's view of a stack of this many boxes. */
  def view(boxes: Int): Region =
    val height = 2 * HalfSide * boxes + 0.5
    Region(-0.75 * height, -0.5, 0.75 * height, height)
