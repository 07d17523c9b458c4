package sims.solver.soft.joints

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.World
import sims.dynamics.joints.{ForceJoint, Joint}
import sims.solver.ShortCopy
import sims.solver.soft.SoftBodies

/** A world's joints as the soft step sees them: each joint's soft constraint (made the first
  * time the joint is stepped and kept, with the impulses it accumulates, while the joint stays
  * in the world), this step's force joints, and the joint trees for the direct solver.
  */
private[sims] final class SoftJoints:
  /** This step's constraints, in world order. */
  val constraints: ArrayBuffer[JointConstraint] = ArrayBuffer.empty[JointConstraint]
  /** This step's force joints (springs), in world order: their forces are applied in every substep. */
  val forceJoints: ArrayBuffer[ForceJoint] = ArrayBuffer.empty[ForceJoint]
  /** Indices of the bodies the force joints act on, each once. */
  val forceBodies: ArrayBuffer[Int] = ArrayBuffer.empty[Int]
  /** The direct solver of joint trees, and the constraints left to the iterative one. */
  val trees: JointTrees = JointTrees()

  // Each joint of the world's list as last seen and its constraint (null for a force joint).
  private var known = new Array[Joint](0)
  private var knownConstraints = new Array[JointConstraint](0)
  private var knownCount = 0
  // The constraints of joints that are in the world, by joint; rebuilt when the list changes.
  private var byJoint = java.util.IdentityHashMap[Joint, JointConstraint]()
  // The map `learn` fills next, kept between calls: a world whose joints change often (ragdolls
  // made and taken away) would otherwise allocate a table of all its joints each time.
  private var spareByJoint = java.util.IdentityHashMap[Joint, JointConstraint]()
  private var forceBodyStamp = new Array[Int](0)
  private var stamp = 0
  // The impulses at the start of the step under way (`beginStep`), for `undoStep`.
  private var startImpulses = new Array[Double](0)
  // The world's revision when the lists were last sorted with no body asleep, or -1: while the
  // joints and the bodies' indices stay the same and no body sleeps, the lists stay as they are.
  private var sortedRevision = -1L

  /** Sorts the world's joints for this step: force joints, joint trees (when `direct`) and the
    * constraints solved iteratively.
    */
  def sort(world: World, bodies: SoftBodies, direct: Boolean): Unit =
    val joints = world.jointList
    val same = sameJoints(joints)
    if !same then learn(joints)
    if same && !bodies.anyAsleep && sortedRevision == world.revision then sortTrees(bodies, direct)
    else
      sortLists(world, bodies)
      sortedRevision = if bodies.anyAsleep then -1L else world.revision
      sortTrees(bodies, direct)

  private def sortTrees(bodies: SoftBodies, direct: Boolean): Unit =
    if direct then trees.build(constraints, bodies) else trees.keepIterative(constraints)

  private def sortLists(world: World, bodies: SoftBodies): Unit =
    constraints.clear()
    forceJoints.clear()
    forceBodies.clear()
    stamp += 1
    if forceBodyStamp.length < world.bodyList.length then forceBodyStamp = new Array[Int](2 * world.bodyList.length)
    var i = 0
    while i < knownCount do
      val c = knownConstraints(i)
      val j = known(i)
      // A joint whose bodies are both asleep (or asleep and fixed) rests with them, its impulses kept.
      if bodies.anyAsleep && restsAsleep(bodies, j.node1.index, j.node2.index) then ()
      else if c != null then constraints += c
      else
        forceJoints += j.asInstanceOf[ForceJoint]
        markForceBody(j.node1.index)
        markForceBody(j.node2.index)
      i += 1

  /** Whether a joint between bodies a and b rests: neither moves this step (each asleep or
    * fixed) and one of them sleeps. A body outside the world (index -1) never rests.
    */
  private def restsAsleep(bodies: SoftBodies, a: Int, b: Int): Boolean =
    a >= 0 && b >= 0 && bodies.invMass(a) == 0 && bodies.invMass(b) == 0 && (bodies.asleep(a) || bodies.asleep(b))

  private def sameJoints(joints: ArrayBuffer[Joint]): Boolean =
    if joints.length != knownCount then false
    else
      var i = 0
      while i < knownCount && (joints(i) eq known(i)) do i += 1
      i == knownCount

  /** Takes the world's list of joints: the constraints of joints still there are kept, joints
    * that left are forgotten, new ones get theirs.
    */
  private def learn(joints: ArrayBuffer[Joint]): Unit =
    val next = spareByJoint // empty
    knownCount = joints.length
    if known.length < knownCount then
      known = new Array[Joint](2 * knownCount)
      knownConstraints = new Array[JointConstraint](2 * knownCount)
    var i = 0
    while i < knownCount do
      val j = joints(i)
      val c = if byJoint.containsKey(j) then byJoint.get(j) else JointConstraint.of(j)
      next.put(j, c)
      known(i) = j
      knownConstraints(i) = c
      i += 1
    java.util.Arrays.fill(known.asInstanceOf[Array[AnyRef]], knownCount, known.length, null)
    java.util.Arrays.fill(knownConstraints.asInstanceOf[Array[AnyRef]], knownCount, knownConstraints.length, null)
    spareByJoint = byJoint
    spareByJoint.clear() // holds no joint that left
    byJoint = next

  private def markForceBody(index: Int): Unit =
    if index >= 0 && forceBodyStamp(index) != stamp then
      forceBodyStamp(index) = stamp
      forceBodies += index

  /** The impulses `joint` carries (a copy; zeros, as many as its constraint has rows, if it was
    * never stepped).
    */
  def impulsesOf(joint: Joint): Array[Double] =
    val c = byJoint.get(joint)
    if c != null then c.impulse.clone() else new Array[Double](JointConstraint.rowsOf(joint))

  /** Sets the impulses `joint` carries (a loaded world's), making its constraint if need be. */
  def setImpulses(joint: Joint, impulses: Array[Double]): Unit =
    var c = byJoint.get(joint)
    if c == null && !byJoint.containsKey(joint) then
      c = JointConstraint.of(joint)
      byJoint.put(joint, c)
    if c == null || c.impulse.length != impulses.length then
      throw IllegalArgumentException(s"$joint carries ${if c == null then 0 else c.impulse.length} impulses, " +
        s"not ${impulses.length}")
    System.arraycopy(impulses, 0, c.impulse, 0, impulses.length)

  /** A copy of every known joint's impulses, for a snapshot of the world. */
  def copyImpulses(): SoftJoints.Saved =
    val joints = ArrayBuffer.empty[Joint]
    val impulses = ArrayBuffer.empty[Array[Double]]
    byJoint.forEach((j, c) => if c != null then { joints += j; impulses += c.impulse.clone() })
    SoftJoints.Saved(joints.toArray, impulses.toArray)

  /** Puts back the impulses of a copy taken by `copyImpulses` (null: none, every impulse 0). */
  def restoreImpulses(saved: SoftJoints.Saved): Unit =
    byJoint.forEach((_, c) => if c != null then java.util.Arrays.fill(c.impulse, 0.0))
    if saved != null then
      var i = 0
      while i < saved.joints.length do
        val c = byJoint.get(saved.joints(i))
        if c != null then System.arraycopy(saved.impulses(i), 0, c.impulse, 0, c.impulse.length)
        i += 1

  /** Marks the start of a step: the impulses of the joints known now, for `undoStep`. */
  def beginStep(): Unit =
    // A joint has at most MaxRows impulses: room for every one without counting them first.
    if startImpulses.length < JointConstraint.MaxRows * knownCount then
      startImpulses = new Array[Double](2 * JointConstraint.MaxRows * knownCount)
    val list = startConstraints(knownCount)
    var total = 0
    var i = 0
    while i < knownCount do
      val c = knownConstraints(i)
      if c != null then
        ShortCopy.doubles(c.impulse, 0, startImpulses, total, c.impulse.length)
        total += c.impulse.length
      if list(i) ne c then list(i) = c // no write barrier for last step's constraint
      i += 1
    startCount = knownCount

  // The constraints `beginStep` saved the impulses of, in order.
  private var startList = new Array[JointConstraint](0)
  private var startCount = 0
  private def startConstraints(n: Int): Array[JointConstraint] =
    if startList.length < n then startList = new Array[JointConstraint](2 * n)
    startList

  /** Puts back the impulses `beginStep` saved (the step failed). */
  def undoStep(): Unit =
    var total = 0
    var i = 0
    while i < startCount do
      val c = startList(i)
      if c != null then
        ShortCopy.doubles(startImpulses, total, c.impulse, 0, c.impulse.length)
        total += c.impulse.length
      i += 1

private[sims] object SoftJoints:
  /** A snapshot's copy of the joints' impulses. */
  final class Saved(val joints: Array[Joint], val impulses: Array[Array[Double]])
