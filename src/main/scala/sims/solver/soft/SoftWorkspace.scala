package sims.solver.soft

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.World
import sims.dynamics.joints.{ForceJoint, Joint}
import sims.solver.soft.SoftBodies.*

/** What the soft step keeps for one world: the bodies' arrays, the contact table (carried from
  * step to step), the collision stage, the joints of the current step and the softness
  * coefficients.
  */
private[sims] final class SoftWorkspace extends sims.solver.CarriedState:
  /** The bodies during a step. */
  val bodies: SoftBodies = SoftBodies()
  /** The contacts, this step's and the last step's. */
  val table: ContactTable = ContactTable()
  /** The collision stage. */
  val finder: ContactFinder = ContactFinder()
  /** What the joints read. */
  val context: SoftContext = SoftContext()
  /** The contacts' softness for the step. */
  val stiffness: ContactStiffness = ContactStiffness()
  /** The joints solved as constraints, and those whose forces are applied in each substep. */
  val constraintJoints, forceJoints: ArrayBuffer[Joint] = ArrayBuffer.empty[Joint]
  /** The direct solver of joint trees, and the joints left to the iterative one. */
  val trees: JointTrees = JointTrees()
  /** Indices of the bodies the force joints act on, each once. */
  val forceBodies: ArrayBuffer[Int] = ArrayBuffer.empty[Int]
  private var forceBodyStamp = new Array[Int](0)
  private var stamp = 0

  /** Sorts the world's joints into force joints, joint trees (when `direct`) and the joints
    * solved iteratively, for this step.
    */
  def sortJoints(world: World, direct: Boolean): Unit =
    constraintJoints.clear()
    forceJoints.clear()
    forceBodies.clear()
    stamp += 1
    if forceBodyStamp.length < world.bodyList.length then forceBodyStamp = new Array[Int](2 * world.bodyList.length)
    val joints = world.jointList
    var i = 0
    while i < joints.length do
      val j = joints(i)
      if j.softForces && j.isInstanceOf[ForceJoint] then
        forceJoints += j
        markForceBody(j.node1.index)
        markForceBody(j.node2.index)
      else constraintJoints += j
      i += 1
    if direct then trees.build(constraintJoints, bodies) else trees.keepIterative(constraintJoints)

  private def markForceBody(index: Int): Unit =
    if index >= 0 && forceBodyStamp(index) != stamp then
      forceBodyStamp(index) = stamp
      forceBodies += index

  // The committed contacts when the step under way began: a failed step that already
  // committed its contacts swaps the generations back.
  private var committedAtStart: Contacts = null

  /** The committed contacts as copies, points and separations after the step's motion. */
  def contactViews(): IndexedSeq[sims.collision.Contact] =
    import ContactTable.*
    val contacts = table.committed
    val hot = contacts.hot
    val state = bodies.state
    IndexedSeq.tabulate(contacts.count) { c =>
      val a = contacts.bodyA(c)
      val b = contacts.bodyB(c)
      val k = contacts.offset(c)
      val nx = hot(k + NormalX)
      val ny = hot(k + NormalY)
      val sA = a * SoftBodies.Stride
      val sB = b * SoftBodies.Stride
      val count = contacts.pointCount(c)
      val points = IndexedSeq.tabulate(count) { p =>
        val q = contacts.hotPoint(c, p)
        val rx = hot(q + AnchorAX); val ry = hot(q + AnchorAY)
        sims.geometry.Vector2D(bodies.startX(a) + state(sA + ShiftX) + state(sA + TurnCos) * rx - state(sA + TurnSin) * ry,
          bodies.startY(a) + state(sA + ShiftY) + state(sA + TurnSin) * rx + state(sA + TurnCos) * ry)
      }
      val separations = IndexedSeq.tabulate(count) { p =>
        val q = contacts.hotPoint(c, p)
        val rAx = hot(q + AnchorAX); val rAy = hot(q + AnchorAY)
        val rBx = hot(q + AnchorBX); val rBy = hot(q + AnchorBY)
        val dx = state(sB + ShiftX) - state(sA + ShiftX) + (state(sB + TurnCos) * rBx - state(sB + TurnSin) * rBy) - (state(sA + TurnCos) * rAx - state(sA + TurnSin) * rAy)
        val dy = state(sB + ShiftY) - state(sA + ShiftY) + (state(sB + TurnSin) * rBx + state(sB + TurnCos) * rBy) - (state(sA + TurnSin) * rAx + state(sA + TurnCos) * rAy)
        dx * nx + dy * ny + hot(q + BaseSeparation)
      }
      def column(offset: Int) = IndexedSeq.tabulate(count)(p => hot(contacts.hotPoint(c, p) + offset))
      sims.collision.Contact(contacts.shapeA(c), contacts.shapeB(c), sims.geometry.Vector2D(nx, ny), points,
        separations, column(NormalImpulse), column(TangentImpulse), column(TotalNormalImpulse))
    }

  def copyState(): AnyRef = table.copyCommitted()
  def restoreState(saved: AnyRef): Unit = table.restoreCommitted(saved.asInstanceOf[Contacts])
  def beginStep(): Unit = committedAtStart = table.committed
  def undoStep(): Unit = if table.committed ne committedAtStart then table.uncommit()
