package sims.dynamics

import scala.collection.mutable.ArrayBuffer

/** A world's joints that break: after the solver's stage, the joints whose reaction exceeds
  * their `breakForce` or `breakTorque` leave the world, recorded as [[JointBreak]]s (put back
  * if the step fails).
  */
trait JointBreaking:
  this: World =>

  /** The joints that broke in the last step (their reaction exceeded `breakForce` or
    * `breakTorque`), removed from the world, in world order.
    */
  def jointBreaks: IndexedSeq[JointBreak] = breaks.toIndexedSeq

  private val breaks = ArrayBuffer.empty[JointBreak]
  // Where each broken joint was in the list, to put it back if the step fails.
  private val brokenAt = ArrayBuffer.empty[Int]

  /** Removes the joints whose reaction exceeds their break limits, recording each break. */
  private[dynamics] def breakJoints(): Unit =
    breaks.clear()
    brokenAt.clear()
    var i = 0
    var removed = 0
    while i < jointList.length do
      val j = jointList(i)
      if j.overloaded then
        breaks += JointBreak(j, j.reactionForce, j.reactionTorque)
        brokenAt += i + removed
        removeJointAt(i)
        removed += 1
      else i += 1

  /** Puts the joints broken in the failed step back where they were. */
  private[dynamics] def unbreakJoints(): Unit =
    for (b, at) <- breaks.zip(brokenAt) do
      jointList.insert(at, b.joint)
      b.joint.world = this
      if !b.joint.collideConnected then b.joint.keepApart(true)
    breaks.clear()
    brokenAt.clear()
