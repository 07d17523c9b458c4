package sims.scenes

import sims.geometry.Vector2D

/** `joint_grid`, Box2D v3's benchmark scene of that name: `side` x `side` discs of radius 0.4
  * on a 1 m grid (column k at x = k, row i at y = -i), each pinned by a revolute joint halfway
  * to its neighbour above and to its left; the top row's seven middle discs are fixed, and the
  * grid falls and swings from them. No two discs collide (Box2D's filter: the grid's category
  * is masked out), so the scene is joints alone: 100 x 100 discs, 19,800 joints.
  */
final case class JointGrid(side: Int = JointGrid.BenchmarkSide) extends LayoutScene:
  import JointGrid.*
  require(side >= 7, s"a joint grid needs a side of at least 7, got $side")

  def name: String = if side == BenchmarkSide then "joint_grid" else s"joint_grid-$side"
  def description: String = s"$side x $side discs pinned to their neighbours, hanging from the top row's middle."
  def view: Region = Region(-side, -2.0 * side, 2.0 * side, 1)

  /** The layout index of the disc in column k, row i. */
  def index(k: Int, i: Int): Int = k * side + i

  lazy val layout: Layout =
    val discs =
      for k <- 0 until side; i <- 0 until side yield
        val fixed = i == 0 && k >= side / 2 - 3 && k <= side / 2 + 3
        SceneBody(Outline.Circle(Radius), Vector2D(k, -i), fixed, if fixed then 0 else 1, Layout.StandardFriction, 0,
          noCollideGroup = 1)
    val joints =
      for
        k <- 0 until side; i <- 0 until side;
        joint <-
          (if i > 0 then Seq(SceneJoint(index(k, i - 1), index(k, i), JointKind.Revolute)) else Nil) ++
            (if k > 0 then Seq(SceneJoint(index(k - 1, i), index(k, i), JointKind.Revolute)) else Nil)
      yield joint
    // A grid hanging from its middle swings out to about its diagonal on either side.
    Layout(discs, joints, Layout.StandardGravity, Layout.StandardTimeStep,
      Region(-1.5 * side, -1.5 * side, 2.5 * side, 1.5 * side))

object JointGrid:
  /** The benchmark's side. */
  val BenchmarkSide: Int = 100
  /** The discs' radius, m. */
  val Radius: Double = 0.4
