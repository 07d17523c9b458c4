package sims.solver.soft

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.World
import sims.dynamics.joints.{ForceJoint, Joint}

/** What the soft step keeps for one world: the bodies' arrays, the contact table (carried from
  * step to step), the collision stage, the joints of the current step and the softness
  * coefficients.
  */
private[sims] final class SoftWorkspace:
  /** The bodies during a step. */
  val bodies: SoftBodies = SoftBodies()
  /** The contacts, this step's and the last step's. */
  val table: ContactTable = ContactTable()
  /** The collision stage. */
  val finder: ContactFinder = ContactFinder()
  /** What the joints read. */
  val context: SoftContext = SoftContext()
  /** Softness of contacts between two moving bodies, and of contacts with a fixed body. */
  val contactSoftness, staticSoftness: Softness = Softness()
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
