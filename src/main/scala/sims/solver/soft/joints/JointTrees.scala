package sims.solver.soft.joints

import scala.collection.mutable.ArrayBuffer
import sims.solver.soft.{Contacts, SoftBodies, SoftContext}
import sims.solver.soft.SoftBodies.*
import JointTrees.Plan

/** The soft step's direct solver for joints that form trees (a chain, a pendulum, a ragdoll):
  * in every pass it solves all the tree's joint rows at once, exactly, in time linear in the
  * number of joints (Baraff 1996, "Linear-time dynamics using Lagrange multipliers"), where
  * one Gauss-Seidel sweep per pass would pass a correction along a 100-link chain only one
  * link per sweep. Its joints are rigid: the solve pass removes the whole position error C
  * within the substep (bias C / h), with a small compliance that keeps a tree near a singular
  * pose from amplifying that bias without bound (see `setUp`); the relax pass is exact and
  * takes the bias velocity out again. A tree that nothing else acts on (see `markTouched`) is
  * left alone by the relax passes before another substep and by the warm start, which would
  * change nothing that lasts: the trees are laid out once for as long as their joints stay.
  *
  * Derivation. With M the moving bodies' mass matrix (fixed bodies are not unknowns: their
  * velocities are given), J the rows' Jacobian and y = -dLambda, the velocity changes dv and
  * impulses of one pass solve the block system
  *   [ M  J^T ] [dv]   [ 0 ]
  *   [ J  0   ] [ y] = [ r ],   r = -(Cdot + bias)
  * whose graph (a node per body and per joint, an edge per body of a joint) is a tree when the
  * joints form no loop through moving bodies. Eliminating nodes leaves first gives
  * D_i = H_ii - sum over children c of H_ic D_c^-1 H_ci, z_i = b_i - sum H_ic D_c^-1 z_c; then
  * from the roots down x_i = D_i^-1 (z_i - H_i,parent x_parent): no fill-in, every block at most
  * 3 x 3. The bodies of a chain's links are eliminated before their joints (see `fold`), so
  * that a chain is solved in its joints' rows alone. Joints in loops (nets, trusses) and joints
  * that give no rows (the mouse joint, a user's) stay with the iterative soft solver.
  */
private[sims] final class JointTrees:
  /** The joints of this step left to the iterative solver, in world order. */
  val iterative: ArrayBuffer[JointConstraint] = ArrayBuffer.empty[JointConstraint]
  private val direct = ArrayBuffer.empty[JointConstraint]
  private val rows = JointRows()
  // Per direct joint t: its moving bodies (-1 when fixed), its bodies' indices (fixed ones
  // too: a fixed body may move at a given velocity) and rows.
  private var body1, body2, index1, index2, rowCount = new Array[Int](0)
  // The elimination tree, nodes in breadth-first order from each root: kind (body or joint),
  // the body index or joint number, size, parent node (-1 for a root), and where the block of
  // the body of the pair (node, parent) starts in its joint's rows (0 for body 1, 6 for body 2).
  private var nodeCount = 0
  private var nodeIsJoint = new Array[Boolean](0)
  private var nodeRef, nodeSize, nodeParent, nodeSide = new Array[Int](0)
  // Folding (see `fold`): whether a body node is folded into its joints; per joint node, the node
  // it is eliminated into and which of its joint's bodies are folded (1: body 1, 2: body 2, 3:
  // both).
  private var nodeFolded = new Array[Boolean](0)
  private var nodeAbove, nodeFolds, childCount = new Array[Int](0)
  private var nodeSlot = new Array[Int](0) // see `planSlots`: -1 for a folded body
  // The trees: tree k's nodes are treeStart(k) until treeStart(k + 1); whether something else
  // acts on it this step (see `markTouched`).
  private var treeCount = 0
  private var treeStart = new Array[Int](1)
  // The nodes the passes visit (all but the folded bodies, which have nothing of their own to
  // solve) are numbered in node order, as slots: tree k's are liveStart(k) until liveStart(k + 1).
  // Every array the passes read is by slot, so that the passes walk them in order, and the
  // loops' index checks on them can be hoisted. Per slot s, from Plan.Stride s (see `Plan`):
  // the node's joint number or body index, its size (a joint's rows, 3 for a body), the slot it
  // is eliminated into (-1 for a root), the offsets in `jacobians` of the block between it and
  // that slot (k x 3: the joint's rows for the body) and of the block beyond a folded body (the
  // joint above's rows for it, -1 unless eliminated into a joint), its folds, and its bodies'
  // offsets in the state (body 1's and body 2's for a joint).
  private var liveStart = new Array[Int](1)
  private var liveCount = 0
  private var plan = new Array[Int](0)
  // Per slot: Jacobians (k x 3 for body 1 at 12 s, for body 2 at 12 s + 6, written by the
  // joints' `rowsAt`), errors (at 2 s), the joint's array of accumulated impulses, and those of
  // its rows here (at 2 s): the passes read and write these, the joint's array gets them back
  // where its own code reads it (see `storeImpulses`). (One array read in place of two: in
  // JavaScript, a swinging chain's step 4% faster.)
  private var jacobians = new Array[Double](0)
  private var positionError = new Array[Double](0)
  private var impulses = new Array[Array[Double]](0)
  private var slotJoint = new Array[JointConstraint](0) // a joint slot's constraint (null for a body)
  private var accumulated = new Array[Double](0)
  // Per slot (see `eliminate`): D, symmetric, its upper triangle at 6 s; the factor kept for the
  // substitution (k x 3, at 6 s); the right side z, w = D^-1 z and the solution x, at 3 s; per
  // joint eliminated into a joint, the block between them (k x k', at 4 s).
  private var d, factor = new Array[Double](0)
  private var z, w, x = new Array[Double](0)
  private var link = new Array[Double](0)
  // Per slot, for this step, at 4 s: a body's mass and moment of inertia; a joint's bodies'
  // inverse masses and moments, body 1's then body 2's.
  private var masses = new Array[Double](0)
  private var treeTouched = new Array[Boolean](0)
  // The joints (and their bodies' indices, whether each moves, rows) the trees were laid out
  // for: while they stay the same, so do the trees (see `sameLayout`).
  private var laidOut = new Array[JointConstraint](0)
  private var laidOutKey = new Array[Int](0)
  private var laidOutCount = -1
  // This step's direct joints whose limits, motor or spring Gauss-Seidel solves, in order.
  private var axial = new Array[JointConstraint](0)
  private var axialCount = 0
  // Bodies in a contact or an iterative joint this step: the stamp of the step that marked them.
  private var bodyMark = new Array[Int](0)
  private var markStamp = 0
  // Graph building.
  private var unionParent, bodyJoints, groundJoints, touched = new Array[Int](0)
  // A breadth-first sweep over a tree's bodies (0 until n) and joints (n + t): queue, visit
  // stamps, predecessors.
  private var queue, visited, previous = new Array[Int](0)
  private var visitStamp, visitedCount = 0
  private var bodyNode = new Array[Int](0)
  // Each body's incident direct joints: incident(start(b) until start(b + 1)).
  private var start, incident, filled = new Array[Int](0)
  private var jointSeen = new Array[Boolean](0)

  /** Sorts this step's constraint joints into trees (solved here) and the rest: kept from the
    * last step when its joints, their bodies and which of those move are the same.
    */
  def build(joints: ArrayBuffer[JointConstraint], bodies: SoftBodies): Unit =
    if !sameLayout(joints, bodies) then
      sortJoints(joints, bodies)
      layOut(bodies)
      remember(joints, bodies)

  /** Whether the trees laid out last are this step's: the same joints in the same order, each
    * between the same bodies, each of those moving or not as before, each with as many rows.
    */
  private def sameLayout(joints: ArrayBuffer[JointConstraint], bodies: SoftBodies): Boolean =
    if joints.length != laidOutCount then false
    else
      var j = 0
      while j < laidOutCount && (joints(j) eq laidOut(j)) && sameKey(j, joints(j), bodies) do j += 1
      j == laidOutCount

  private def sameKey(j: Int, constraint: JointConstraint, bodies: SoftBodies): Boolean =
    val k = 5 * j
    laidOutKey(k) == constraint.joint.node1.index && laidOutKey(k + 1) == constraint.joint.node2.index &&
    laidOutKey(k + 2) == moving(constraint.joint.node1, bodies) &&
    laidOutKey(k + 3) == moving(constraint.joint.node2, bodies) && laidOutKey(k + 4) == constraint.directRows

  private def remember(joints: ArrayBuffer[JointConstraint], bodies: SoftBodies): Unit =
    laidOutCount = joints.length
    if laidOut.length < laidOutCount then
      laidOut = new Array[JointConstraint](2 * laidOutCount)
      laidOutKey = new Array[Int](10 * laidOutCount)
    var j = 0
    while j < laidOutCount do
      val constraint = joints(j)
      val k = 5 * j
      laidOut(j) = constraint
      laidOutKey(k) = constraint.joint.node1.index
      laidOutKey(k + 1) = constraint.joint.node2.index
      laidOutKey(k + 2) = moving(constraint.joint.node1, bodies)
      laidOutKey(k + 3) = moving(constraint.joint.node2, bodies)
      laidOutKey(k + 4) = constraint.directRows
      j += 1
    java.util.Arrays.fill(laidOut.asInstanceOf[Array[AnyRef]], laidOutCount, laidOut.length, null)

  private def sortJoints(joints: ArrayBuffer[JointConstraint], bodies: SoftBodies): Unit =
    direct.clear()
    iterative.clear()
    val n = bodies.count
    if unionParent.length < n then
      unionParent = new Array[Int](2 * n); bodyJoints = new Array[Int](2 * n); groundJoints = new Array[Int](2 * n)
      touched = new Array[Int](2 * n); bodyNode = new Array[Int](2 * n)
    var i = 0
    while i < n do { unionParent(i) = i; bodyJoints(i) = 0; groundJoints(i) = 0; touched(i) = 0; i += 1 }
    // Components of the moving bodies joined by joints that give rows.
    var j = 0
    while j < joints.length do
      val constraint = joints(j)
      if constraint.directRows > 0 then
        val a = moving(constraint.joint.node1, bodies)
        val b = moving(constraint.joint.node2, bodies)
        if a >= 0 && b >= 0 then unionParent(find(a)) = find(b)
      j += 1
    // Per component (at its root): bodies + joints - 1 must equal the body-joint edges.
    j = 0
    while j < joints.length do
      val constraint = joints(j)
      if constraint.directRows > 0 then
        val a = moving(constraint.joint.node1, bodies)
        val b = moving(constraint.joint.node2, bodies)
        val some = if a >= 0 then a else b
        if some >= 0 then
          val root = find(some)
          bodyJoints(root) += 1 // joints of the component, less its edges, plus its bodies
          if a >= 0 then { bodyJoints(root) -= 1; if touched(a) == 0 then { touched(a) = 1; bodyJoints(root) += 1 } }
          if b >= 0 then { bodyJoints(root) -= 1; if touched(b) == 0 then { touched(b) = 1; bodyJoints(root) += 1 } }
          if a < 0 || b < 0 then groundJoints(root) += 1
      j += 1
    // bodyJoints(root) is now bodies + joints - edges: 1 exactly for a tree. Fixed bodies are
    // one ground that does not move: two joints to it close a loop through it (and would make a
    // singular pivot), so a tree holds at most one; it becomes the tree's root.
    j = 0
    while j < joints.length do
      val constraint = joints(j)
      val a = moving(constraint.joint.node1, bodies)
      val b = moving(constraint.joint.node2, bodies)
      val some = if a >= 0 then a else b
      constraint.inTree =
        constraint.directRows > 0 && some >= 0 && bodyJoints(find(some)) == 1 && groundJoints(find(some)) <= 1
      if constraint.inTree then direct += constraint else iterative += constraint
      j += 1

  /** Leaves every joint to the iterative solver. */
  def keepIterative(joints: ArrayBuffer[JointConstraint]): Unit =
    direct.clear()
    iterative.clear()
    iterative ++= joints
    var j = 0
    while j < joints.length do { joints(j).inTree = false; j += 1 }
    nodeCount = 0
    treeCount = 0
    liveCount = 0
    laidOutCount = -1

  /** A body's index if it moves (has a finite mass), else -1. */
  private def moving(body: sims.dynamics.Body, bodies: SoftBodies): Int =
    val i = body.index
    if i >= 0 && i < bodies.count && bodies.invMass(i) != 0 then i else -1

  private def find(i: Int): Int =
    var root = i
    while unionParent(root) != root do root = unionParent(root)
    var k = i
    while unionParent(k) != root do
      val next = unionParent(k)
      unionParent(k) = root
      k = next
    root

  /** The elimination tree: breadth-first from the lowest body index of each component. */
  private def layOut(bodies: SoftBodies): Unit =
    val joints = direct.length
    if body1.length < joints then
      body1 = new Array[Int](2 * joints); body2 = new Array[Int](2 * joints); rowCount = new Array[Int](2 * joints)
      index1 = new Array[Int](2 * joints); index2 = new Array[Int](2 * joints)
    var t = 0
    while t < joints do
      body1(t) = moving(direct(t).joint.node1, bodies)
      body2(t) = moving(direct(t).joint.node2, bodies)
      index1(t) = direct(t).joint.node1.index
      index2(t) = direct(t).joint.node2.index
      rowCount(t) = direct(t).directRows
      t += 1
    // Incidence lists of the bodies (joints in order), in compressed arrays.
    val n = bodies.count
    if start.length < n + 1 then start = new Array[Int](2 * n + 1)
    java.util.Arrays.fill(start, 0, n + 1, 0)
    t = 0
    while t < joints do
      if body1(t) >= 0 then start(body1(t) + 1) += 1
      if body2(t) >= 0 then start(body2(t) + 1) += 1
      t += 1
    var i = 0
    while i < n do { start(i + 1) += start(i); i += 1 }
    if incident.length < start(n) then incident = new Array[Int](2 * start(n))
    if filled.length < n then filled = new Array[Int](2 * n)
    java.util.Arrays.fill(filled, 0, n, 0)
    t = 0
    while t < joints do
      if body1(t) >= 0 then { incident(start(body1(t)) + filled(body1(t))) = t; filled(body1(t)) += 1 }
      if body2(t) >= 0 then { incident(start(body2(t)) + filled(body2(t))) = t; filled(body2(t)) += 1 }
      t += 1
    val capacity = n + joints
    if nodeIsJoint.length < capacity then
      // Room to grow, as the other arrays: a world that gains bodies one by one is laid out anew
      // at each change, and must not allocate each time.
      val room = 2 * capacity
      nodeIsJoint = new Array[Boolean](room)
      nodeRef = new Array[Int](room); nodeSize = new Array[Int](room); nodeParent = new Array[Int](room)
      nodeSide = new Array[Int](room)
      nodeFolded = new Array[Boolean](room)
      nodeAbove = new Array[Int](room); nodeFolds = new Array[Int](room); childCount = new Array[Int](room)
      nodeSlot = new Array[Int](room)
      plan = new Array[Int](Plan.Stride * room)
      jacobians = new Array[Double](12 * room); positionError = new Array[Double](2 * room)
      impulses = new Array[Array[Double]](room)
      slotJoint = new Array[JointConstraint](room)
      accumulated = new Array[Double](2 * room)
      d = new Array[Double](6 * room); factor = new Array[Double](6 * room)
      z = new Array[Double](3 * room); w = new Array[Double](3 * room); x = new Array[Double](3 * room)
      link = new Array[Double](4 * room)
      masses = new Array[Double](4 * room)
    java.util.Arrays.fill(bodyNode, 0, n, -1)
    if jointSeen.length < joints then jointSeen = new Array[Boolean](2 * joints)
    java.util.Arrays.fill(jointSeen, 0, joints, false)
    if queue.length < capacity then
      queue = new Array[Int](2 * capacity); visited = new Array[Int](2 * capacity); previous = new Array[Int](2 * capacity)
      visitStamp = 0
    nodeCount = 0
    treeCount = 0
    // Each tree from its root (see `rootOf`), the trees in the order of their first joint.
    t = 0
    while t < joints do
      if !jointSeen(t) then
        if treeStart.length < treeCount + 2 then treeStart = java.util.Arrays.copyOf(treeStart, 2 * (treeCount + 2))
        treeStart(treeCount) = nodeCount
        val root = rootOf(n + t, n)
        if root >= n then
          jointSeen(root - n) = true
          grow(addNode(isJoint = true, root - n, rowCount(root - n), -1))
        else
          bodyNode(root) = addNode(isJoint = false, root, 3, -1)
          grow(nodeCount - 1)
        treeCount += 1
      t += 1
    treeStart(treeCount) = nodeCount
    if treeTouched.length < treeCount then treeTouched = new Array[Boolean](2 * treeCount)
    fold()
    planSlots()

  /** Folds every body that is not a tree's root and holds at most one joint below it (a chain's
    * link, a leaf) into its joints: its mass matrix is diagonal, so it is eliminated first, at no
    * cost, and its joints meet directly (its joint below is eliminated into its joint above,
    * through a block -J_below M^-1 J_above^T, and each joint's own block gains -J M^-1 J^T). A
    * chain is then solved in its joints' rows alone, 2 x 2 blocks instead of a 3 x 3 block per
    * link. Bodies where the tree branches stay nodes of their own: folded, they would couple all
    * their joints at once.
    */
  private def fold(): Unit =
    java.util.Arrays.fill(childCount, 0, nodeCount, 0)
    var node = 0
    while node < nodeCount do
      if nodeParent(node) >= 0 then childCount(nodeParent(node)) += 1
      node += 1
    node = 0
    while node < nodeCount do
      nodeFolded(node) = !nodeIsJoint(node) && nodeParent(node) >= 0 && childCount(node) <= 1
      node += 1
    node = 0
    while node < nodeCount do
      if nodeIsJoint(node) then
        val parent = nodeParent(node)
        nodeAbove(node) = if parent >= 0 && nodeFolded(parent) then nodeParent(parent) else parent
        val joint = nodeRef(node)
        nodeFolds(node) = (if folded(body1(joint)) then 1 else 0) | (if folded(body2(joint)) then 2 else 0)
      node += 1

  private def folded(body: Int): Boolean = body >= 0 && nodeFolded(bodyNode(body))

  /** Numbers each tree's nodes that are not folded as slots, in node order, and writes their
    * plan (see `plan`) and each joint's array of accumulated impulses.
    */
  private def planSlots(): Unit =
    if liveStart.length < treeCount + 1 then liveStart = new Array[Int](2 * (treeCount + 1))
    var count = 0
    var tree = 0
    while tree < treeCount do
      liveStart(tree) = count
      var node = treeStart(tree)
      while node < treeStart(tree + 1) do
        if !nodeFolded(node) then
          nodeSlot(node) = count
          count += 1
        else nodeSlot(node) = -1
        node += 1
      tree += 1
    liveStart(treeCount) = count
    liveCount = count
    java.util.Arrays.fill(impulses.asInstanceOf[Array[AnyRef]], 0, impulses.length, null) // no joint that left
    java.util.Arrays.fill(slotJoint.asInstanceOf[Array[AnyRef]], 0, slotJoint.length, null)
    var node = 0
    while node < nodeCount do
      val slot = nodeSlot(node)
      if slot >= 0 then
        val o = Plan.Stride * slot
        val ref = nodeRef(node)
        plan(o + Plan.Ref) = ref
        plan(o + Plan.Size) = nodeSize(node)
        plan(o + Plan.Over) = -1
        if nodeIsJoint(node) then
          val above = nodeAbove(node)
          plan(o + Plan.Above) = if above >= 0 then nodeSlot(above) else -1
          plan(o + Plan.Block) = if nodeParent(node) >= 0 then 12 * slot + nodeSide(node) else -1
          if above >= 0 && nodeIsJoint(above) then
            plan(o + Plan.Over) = 12 * nodeSlot(above) + nodeSide(nodeParent(node))
          plan(o + Plan.Folds) = nodeFolds(node)
          plan(o + Plan.State1) = index1(ref) * SoftBodies.Stride
          plan(o + Plan.State2) = index2(ref) * SoftBodies.Stride
          impulses(slot) = direct(ref).impulse
          slotJoint(slot) = direct(ref)
        else
          val parent = nodeParent(node)
          plan(o + Plan.Above) = if parent >= 0 then nodeSlot(parent) else -1
          plan(o + Plan.Block) = if parent >= 0 then 12 * nodeSlot(parent) + nodeSide(node) else -1
          plan(o + Plan.Folds) = 0
          plan(o + Plan.State1) = ref * SoftBodies.Stride
          plan(o + Plan.State2) = 0
      node += 1

  /** The root of the tree holding `element` (a body b < n or a joint n + t): its centre, the
    * middle of a longest path, found by two sweeps (the farthest element from any is an end of a
    * longest path; the farthest from that end is the other). Eliminated from the leaves towards
    * its centre, a tree's branches are independent chains of arithmetic of about half the tree's
    * depth, which the processor overlaps: a chain hung from one end is solved as two half chains
    * at once. A joint to the ground is the root unless that centre is a joint on the plain chain
    * that starts at it (see `onChain`).
    */
  private def rootOf(element: Int, n: Int): Int =
    val end = sweep(element, n)
    var k = 0
    var ground = -1
    while ground < 0 && k < visitedCount do
      val e = queue(k)
      if e >= n && (body1(e - n) < 0 || body2(e - n) < 0) then ground = e
      k += 1
    var middle = sweep(end, n)
    var length = 0
    var e = middle
    while e != end do { e = previous(e); length += 1 }
    k = 0
    while k < length / 2 do { middle = previous(middle); k += 1 }
    if ground < 0 then middle
    else
      if middle < n then middle = previous(middle) // a joint: its body would not be folded
      if onChain(middle - n, ground - n) then middle else ground

  /** Whether `joint` lies on the plain chain that starts at joint `ground` (to the ground):
    * ground, its body, the body's other joint, and on while each body holds two joints. Every
    * body there is folded into its two joints (see `fold`) when `joint` is the root, so each of
    * those joints, eliminated from the ground up, has the whole mass of the body above it for its
    * pivot. Below a body that is not folded (where the tree branches), a joint's pivot would
    * hold only what the joints below it left of its lower body: after a revolute joint to the
    * ground, one turn for the two rows of the revolute joint above it, a singular pivot.
    */
  private def onChain(joint: Int, ground: Int): Boolean =
    var t = ground
    var body = math.max(body1(ground), body2(ground))
    while t != joint && body >= 0 && start(body + 1) - start(body) == 2 do
      t = if incident(start(body)) == t then incident(start(body) + 1) else incident(start(body))
      body = if body1(t) == body then body2(t) else body1(t)
    t == joint

  /** Visits the tree of `from` breadth first (bodies b < n, joints n + t), leaving each
    * element's predecessor in `previous` and the elements visited in `queue(0 until
    * visitedCount)`; returns the last element visited, one of the farthest.
    */
  private def sweep(from: Int, n: Int): Int =
    visitStamp += 1
    var head = 0
    var tail = 1
    queue(0) = from
    visited(from) = visitStamp
    while head < tail do
      val e = queue(head)
      head += 1
      if e < n then
        var k = start(e)
        while k < start(e + 1) do
          val next = n + incident(k)
          if visited(next) != visitStamp then
            visited(next) = visitStamp; previous(next) = e; queue(tail) = next; tail += 1
          k += 1
      else
        val joint = e - n
        var side = 0
        while side < 2 do
          val next = if side == 0 then body1(joint) else body2(joint)
          if next >= 0 && visited(next) != visitStamp then
            visited(next) = visitStamp; previous(next) = e; queue(tail) = next; tail += 1
          side += 1
    visitedCount = tail
    queue(tail - 1)

  /** Adds the tree below `root`, breadth first: a body's children are its other joints, a
    * joint's its other moving body.
    */
  private def grow(root: Int): Unit =
    var head = root
    while head < nodeCount do
      if !nodeIsJoint(head) then
        val b = nodeRef(head)
        var e = start(b)
        while e < start(b + 1) do
          val joint = incident(e)
          if !jointSeen(joint) then
            jointSeen(joint) = true
            addNode(isJoint = true, joint, rowCount(joint), head)
          e += 1
      else
        val joint = nodeRef(head)
        var side = 0
        while side < 2 do
          val body = if side == 0 then body1(joint) else body2(joint)
          if body >= 0 && bodyNode(body) < 0 then bodyNode(body) = addNode(isJoint = false, body, 3, head)
          side += 1
      head += 1

  private def addNode(isJoint: Boolean, ref: Int, size: Int, parent: Int): Int =
    val node = nodeCount
    nodeIsJoint(node) = isJoint
    nodeRef(node) = ref
    nodeSize(node) = size
    nodeParent(node) = parent
    // The joint's rows for the body of the pair (node, parent): body 1's block (0) or body 2's (6).
    nodeSide(node) =
      if parent < 0 then 0
      else
        val joint = if isJoint then ref else nodeRef(parent)
        val body = if isJoint then nodeRef(parent) else ref
        if body1(joint) == body then 0 else 6
    nodeCount += 1
    node

  /** Decides, for this step, which trees' joints apply their accumulated impulses in the warm
    * start: those with a body in one of the first `active` contacts of `contacts` or in a joint
    * solved iteratively, and those with a joint whose limits, motor or spring Gauss-Seidel solves
    * ([[JointConstraint.solvesAxial]]). The others' warm start would change nothing: a tree's
    * exact solve sets its rows' velocities whatever they were (an impulse J^T lambda along its
    * own rows is undone by it exactly), and only what is solved before it in a pass sees the
    * joints' load. Takes the trees' bodies' masses for the step too.
    */
  def markTouched(contacts: Contacts, bodies: SoftBodies): Unit =
    takeMasses(bodies)
    loadImpulses()
    listAxial()
    if treeCount > 0 then
      if bodyMark.length < bodies.count then bodyMark = new Array[Int](2 * bodies.count)
      markStamp += 1
      var c = 0
      while c < contacts.active do
        bodyMark(contacts.bodyA(c)) = markStamp
        bodyMark(contacts.bodyB(c)) = markStamp
        c += 1
      var j = 0
      while j < iterative.length do
        mark(iterative(j).joint.node1.index)
        mark(iterative(j).joint.node2.index)
        j += 1
      var tree = 0
      while tree < treeCount do
        var needed = false
        var node = treeStart(tree)
        while !needed && node < treeStart(tree + 1) do
          needed =
            if nodeIsJoint(node) then direct(nodeRef(node)).solvesAxial
            else bodyMark(nodeRef(node)) == markStamp
          node += 1
        treeTouched(tree) = needed
        tree += 1

  /** The direct joints with rows for Gauss-Seidel this step: the passes call no one else's. */
  private def listAxial(): Unit =
    if axial.length < direct.length then axial = new Array[JointConstraint](2 * direct.length)
    java.util.Arrays.fill(axial.asInstanceOf[Array[AnyRef]], 0, axialCount, null)
    axialCount = 0
    var t = 0
    while t < direct.length do
      if direct(t).solvesAxial then
        axial(axialCount) = direct(t)
        axialCount += 1
      t += 1

  /** Each slot's masses for this step's passes (see `masses`). */
  private def takeMasses(bodies: SoftBodies): Unit =
    var slot = 0
    while slot < liveCount do
      val m = 4 * slot
      val ref = plan(Plan.Stride * slot + Plan.Ref)
      if plan(Plan.Stride * slot + Plan.Size) < 3 then
        masses(m) = bodies.invMass(index1(ref)); masses(m + 1) = bodies.invI(index1(ref))
        masses(m + 2) = bodies.invMass(index2(ref)); masses(m + 3) = bodies.invI(index2(ref))
      else
        masses(m) = 1 / bodies.invMass(ref)
        masses(m + 1) = 1 / bodies.invI(ref)
      slot += 1

  private def mark(index: Int): Unit = if index >= 0 && index < bodyMark.length then bodyMark(index) = markStamp

  /** Applies the accumulated impulses of the joints of the trees that need it (see
    * `markTouched`). The others start every substep from 0 without being visited: their solve
    * pass takes the accumulated impulse as 0 and sets it (see `solve`). (The solve pass's
    * compliance reads the accumulated impulse as what the substep applied so far: with nothing
    * applied, 0. Its exact solve then gives the same impulses and velocities as after a warm
    * start.)
    */
  def warmStart(context: SoftContext): Unit =
    var tree = 0
    while tree < treeCount do
      if treeTouched(tree) then
        storeImpulses(liveStart(tree), liveStart(tree + 1))
        // Every joint is a slot (only bodies are folded), in node order.
        var slot = liveStart(tree)
        while slot < liveStart(tree + 1) do
          val joint = slotJoint(slot)
          if joint != null then joint.warmStart(context)
          slot += 1
      tree += 1

  /** Gives each joint of the trees its rows' accumulated impulses from the passes (for its
    * warm start, its reaction and the next step): called after the step's last pass.
    */
  def storeImpulses(): Unit = storeImpulses(0, liveCount)

  private def storeImpulses(from: Int, until: Int): Unit =
    var slot = from
    while slot < until do
      val size = plan(Plan.Stride * slot + Plan.Size)
      if size < 3 then
        val impulse = impulses(slot)
        impulse(0) = accumulated(2 * slot)
        if size == 2 then impulse(1) = accumulated(2 * slot + 1)
      slot += 1

  /** Takes each joint's rows' accumulated impulses, as the step begins. */
  private def loadImpulses(): Unit =
    var slot = 0
    while slot < liveCount do
      val size = plan(Plan.Stride * slot + Plan.Size)
      if size < 3 then
        val impulse = impulses(slot)
        accumulated(2 * slot) = impulse(0)
        if size == 2 then accumulated(2 * slot + 1) = impulse(1)
      slot += 1

  /** One pass over every tree: the rows the trees leave to Gauss-Seidel (limits, motors,
    * springs), then the trees' own rows solved exactly, with the bias C / h (`useBias`) or
    * without; when not `always`, only the trees that something else acts on (see
    * `markTouched`): for the others the pass would change nothing that lasts (a relax pass
    * before another substep's solve pass, which sets their rows' velocities whatever they were).
    */
  def solve(context: SoftContext, useBias: Boolean, always: Boolean): Unit =
    if direct.nonEmpty then
      // The rows the trees leave to Gauss-Seidel first, as a joint solved iteratively does
      // before its own point constraint.
      var t = 0
      while t < axialCount do
        axial(t).solveAxial(context, useBias)
        t += 1
      val state = context.bodies.state
      var tree = 0
      while tree < treeCount do
        if always || treeTouched(tree) then
          val from = liveStart(tree)
          val until = liveStart(tree + 1)
          // The joints' rows at the current positions first (a loop of its own: fused into
          // `setUp` it measured 8% slower on a chain).
          var slot = from
          while slot < until do
            val o = Plan.Stride * slot
            if plan(o + Plan.Size) < 3 then
              rows.target(jacobians, 12 * slot, positionError, 2 * slot)
              slotJoint(slot).rowsAt(context, rows)
            slot += 1
          // A tree the warm start left alone starts the substep's solve pass from 0.
          val fresh = useBias && !treeTouched(tree)
          setUp(context, state, useBias, fresh, from, until)
          eliminate(from, until)
          substitute(state, fresh, from, until)
        tree += 1

  /** For the slots `from until until`, each one's block of H and right side: a body's mass
    * matrix and 0; a joint's -G (its compliance, in the solve pass) less its folded bodies'
    * J M^-1 J^T, and -(Cdot + bias + G lambdaAcc); the block between a joint and the joint above
    * it (see `fold`).
    */
  private def setUp(context: SoftContext, state: Array[Double], useBias: Boolean, fresh: Boolean, from: Int,
      until: Int): Unit =
    // A compliance G = Compliance K in the solve pass, K the joint's own effective mass
    // matrix (its two bodies alone): J dv + Cdot + C / h + G (acc + dLambda) = 0, so D = -G
    // and G acc on the right; the relax pass is exact (G = 0, no bias). Exact with bias, a
    // tree near a singular pose (a light body between two links pulled straight) has a
    // near-singular Schur complement and turned an error of centimetres into a velocity
    // of km/s, which a contact solved in the same pass handed to a ball as momentum
    // (kinetic energy up 2.7-fold in zero gravity); with G a joint's response to its error
    // stays within about 1 / Compliance times what its own bodies alone would give.
    val compliance = if useBias then JointTrees.Compliance else 0.0
    val inverseH = context.inverseH
    val plan = this.plan; val masses = this.masses; val d = this.d; val z = this.z
    var slot = from
    while slot < until do
      val p = Plan.Stride * slot
      val o = 6 * slot
      val v = 3 * slot
      val size = plan(p + Plan.Size)
      if size < 3 then
        val j1 = 12 * slot
        val j2 = j1 + 6
        val s1 = plan(p + Plan.State1)
        val s2 = plan(p + Plan.State2)
        val m1 = masses(4 * slot); val i1 = masses(4 * slot + 1)
        val m2 = masses(4 * slot + 2); val i2 = masses(4 * slot + 3)
        // Each body's share of K that D takes: the compliance's, and all of a folded body's.
        val folds = plan(p + Plan.Folds)
        val share1 = if (folds & 1) != 0 then 1 + compliance else compliance
        val share2 = if (folds & 2) != 0 then 1 + compliance else compliance
        val acc0 = if fresh then 0.0 else accumulated(2 * slot)
        val cdot0 = rowVelocity(j1, state, s1) + rowVelocity(j2, state, s2)
        val bias0 = if useBias then positionError(2 * slot) * inverseH else 0.0
        val a00 = coupling(j1, j1, m1, i1); val b00 = coupling(j2, j2, m2, i2)
        val g00 = compliance * (a00 + b00)
        d(o) = -(share1 * a00 + share2 * b00)
        if size == 1 then z(v) = -(cdot0 + bias0 + g00 * acc0)
        else
          val cdot1 = rowVelocity(j1 + 3, state, s1) + rowVelocity(j2 + 3, state, s2)
          val bias1 = if useBias then positionError(2 * slot + 1) * inverseH else 0.0
          val a01 = coupling(j1, j1 + 3, m1, i1); val b01 = coupling(j2, j2 + 3, m2, i2)
          val a11 = coupling(j1 + 3, j1 + 3, m1, i1); val b11 = coupling(j2 + 3, j2 + 3, m2, i2)
          val g01 = compliance * (a01 + b01)
          val g11 = compliance * (a11 + b11)
          val acc1 = if fresh then 0.0 else accumulated(2 * slot + 1)
          d(o + 1) = -(share1 * a01 + share2 * b01); d(o + 3) = -(share1 * a11 + share2 * b11)
          z(v) = -(cdot0 + bias0 + g00 * acc0 + g01 * acc1)
          z(v + 1) = -(cdot1 + bias1 + g01 * acc0 + g11 * acc1)
        val over = plan(p + Plan.Over)
        if over >= 0 then
          // The folded body between them is one of this joint's two.
          val below = plan(p + Plan.Block)
          val above = plan(p + Plan.Above)
          if below == j1 then setLink(slot, size, below, over, above, m1, i1)
          else setLink(slot, size, below, over, above, m2, i2)
      else
        val mass = masses(4 * slot)
        d(o) = mass; d(o + 1) = 0; d(o + 2) = 0
        d(o + 3) = mass; d(o + 4) = 0
        d(o + 5) = masses(4 * slot + 1)
        z(v) = 0; z(v + 1) = 0; z(v + 2) = 0
      slot += 1

  /** The block B between joint `slot` (of `size` rows, its rows for the folded body at `below`)
    * and the joint `above` it (its rows for that body at `over`), through the folded body
    * (inverse mass m, inverse moment i): -J M^-1 J_above^T, B(r, q) at 4 slot + 2 r + q (0 where
    * either joint has one row).
    */
  private inline def setLink(slot: Int, size: Int, below: Int, over: Int, above: Int, m: Double, i: Double): Unit =
    val two = plan(Plan.Stride * above + Plan.Size) == 2
    val l = 4 * slot
    link(l) = -coupling(below, over, m, i)
    link(l + 1) = if two then -coupling(below, over + 3, m, i) else 0.0
    if size == 2 then
      link(l + 2) = -coupling(below + 3, over, m, i)
      link(l + 3) = if two then -coupling(below + 3, over + 3, m, i) else 0.0
    else
      link(l + 2) = 0.0
      link(l + 3) = 0.0

  /** The slots `from until until`, leaves first: each one's D is final once its children are
    * eliminated; it is inverted and eliminated into the slot above it:
    * D_p -= H_pc D_c^-1 H_cp and z_p -= H_pc D_c^-1 z_c, where H_pc is J^T (3 x k) for a joint
    * below a body, J (k x 3) for a body below a joint, and B^T for a joint below a joint (see
    * `fold`). Kept for the substitution: w_c = D_c^-1 z_c, and the factor D_c^-1 J or D_c^-1 B
    * (a joint) or J D_c^-1 (a body). Blocks are symmetric, stored as their upper triangle:
    * (0, 0) (0, 1) (0, 2) (1, 1) (1, 2) (2, 2) at offsets 0 to 5 (a 2 x 2 block uses 0, 1 and 3).
    * Every pivot is regular: a body's D is its mass matrix plus what its subtree adds (positive
    * definite), a joint's -J D^-1 J^T of the bodies below it and its folded bodies' -J M^-1 J^T,
    * which a joint to the ground only lacks as its tree's root.
    */
  private def eliminate(from: Int, until: Int): Unit =
    val plan = this.plan; val d = this.d; val z = this.z; val w = this.w
    var slot = until - 1
    while slot >= from do
      val p = Plan.Stride * slot
      val o = 6 * slot
      val v = 3 * slot
      val size = plan(p + Plan.Size)
      val above = plan(p + Plan.Above)
      if size < 3 then
        // D^-1, symmetric: i00, i01, i11 (i00 alone for one row); a singular block gives 0.
        val two = size == 2
        var i00, i01, i11 = 0.0
        if two then
          val a = d(o); val b = d(o + 1); val c = d(o + 3)
          var det = a * c - b * b
          if det != 0 then det = 1 / det
          i00 = c * det; i01 = -b * det; i11 = a * det
        else if d(o) != 0 then i00 = 1 / d(o)
        val z0 = z(v); val z1 = if two then z(v + 1) else 0.0
        val y0 = i00 * z0 + i01 * z1
        val y1 = i01 * z0 + i11 * z1
        w(v) = y0; w(v + 1) = y1
        if above >= 0 then
          val aboveSize = plan(Plan.Stride * above + Plan.Size)
          if aboveSize < 3 then eliminateIntoJoint(slot, size, above, aboveSize, i00, i01, i11, y0, y1)
          else eliminateIntoBody(slot, size, plan(p + Plan.Block), above, i00, i01, i11, y0, y1)
      else
        // The symmetric 3 x 3 inverse by cofactors (a singular block gives 0).
        val a = d(o); val b = d(o + 1); val c = d(o + 2); val e = d(o + 3); val f = d(o + 4); val i = d(o + 5)
        val c00 = e * i - f * f; val c01 = c * f - b * i; val c02 = b * f - c * e
        var det = a * c00 + b * c01 + c * c02
        if det != 0 then det = 1 / det
        val i00 = c00 * det; val i01 = c01 * det; val i02 = c02 * det
        val i11 = (a * i - c * c) * det; val i12 = (b * c - a * f) * det; val i22 = (a * e - b * b) * det
        val z0 = z(v); val z1 = z(v + 1); val z2 = z(v + 2)
        w(v) = i00 * z0 + i01 * z1 + i02 * z2
        w(v + 1) = i01 * z0 + i11 * z1 + i12 * z2
        w(v + 2) = i02 * z0 + i12 * z1 + i22 * z2
        if above >= 0 then
          val q = 6 * above
          val qv = 3 * above
          // F = J D^-1 (k x 3); D_p -= F J^T, z_p -= F z
          val jo = plan(p + Plan.Block)
          val a0 = jacobians(jo); val a1 = jacobians(jo + 1); val a2 = jacobians(jo + 2)
          val f0 = a0 * i00 + a1 * i01 + a2 * i02
          val f1 = a0 * i01 + a1 * i11 + a2 * i12
          val f2 = a0 * i02 + a1 * i12 + a2 * i22
          factor(o) = f0; factor(o + 1) = f1; factor(o + 2) = f2
          d(q) -= f0 * a0 + f1 * a1 + f2 * a2
          z(qv) -= f0 * z0 + f1 * z1 + f2 * z2
          if plan(Plan.Stride * above + Plan.Size) == 2 then
            val b0 = jacobians(jo + 3); val b1 = jacobians(jo + 4); val b2 = jacobians(jo + 5)
            val h0 = b0 * i00 + b1 * i01 + b2 * i02
            val h1 = b0 * i01 + b1 * i11 + b2 * i12
            val h2 = b0 * i02 + b1 * i12 + b2 * i22
            factor(o + 3) = h0; factor(o + 4) = h1; factor(o + 5) = h2
            d(q + 1) -= f0 * b0 + f1 * b1 + f2 * b2
            d(q + 3) -= h0 * b0 + h1 * b1 + h2 * b2
            z(qv + 1) -= h0 * z0 + h1 * z1 + h2 * z2
      slot -= 1

  /** Joint `slot` of `size` rows (D^-1 = (i00, i01; i01, i11), y = D^-1 z) into the joint `above`
    * of `aboveSize` rows, through the block B (see `setLink`): G = D^-1 B kept, D_above -= B^T G,
    * z_above -= B^T y. (Where either has one row, B's other entries are 0: so are G's and the
    * updates'.)
    */
  private inline def eliminateIntoJoint(slot: Int, size: Int, above: Int, aboveSize: Int, i00: Double, i01: Double,
      i11: Double, y0: Double, y1: Double): Unit =
    val l = 4 * slot
    val o = 6 * slot
    val q = 6 * above
    val qv = 3 * above
    val b00 = link(l)
    if size == 1 && aboveSize == 1 then
      // A chain of one-row joints (distance joints): scalars.
      val g00 = i00 * b00
      factor(o) = g00
      d(q) -= b00 * g00
      z(qv) -= b00 * y0
    else
      val b01 = link(l + 1); val b10 = link(l + 2); val b11 = link(l + 3)
      val g00 = i00 * b00 + i01 * b10; val g01 = i00 * b01 + i01 * b11
      val g10 = i01 * b00 + i11 * b10; val g11 = i01 * b01 + i11 * b11
      factor(o) = g00; factor(o + 1) = g01; factor(o + 2) = g10; factor(o + 3) = g11
      d(q) -= b00 * g00 + b10 * g10
      d(q + 1) -= b00 * g01 + b10 * g11
      d(q + 3) -= b01 * g01 + b11 * g11
      z(qv) -= b00 * y0 + b10 * y1
      z(qv + 1) -= b01 * y0 + b11 * y1

  /** Joint `slot` of `size` rows (D^-1 = (i00, i01; i01, i11), y = D^-1 z, its rows for the body
    * at `jo`) into the body `above`: G = D^-1 J kept, D_above -= J^T G, z_above -= J^T y.
    */
  private inline def eliminateIntoBody(slot: Int, size: Int, jo: Int, above: Int, i00: Double, i01: Double,
      i11: Double, y0: Double, y1: Double): Unit =
    val o = 6 * slot
    val q = 6 * above
    val qv = 3 * above
    val a0 = jacobians(jo); val a1 = jacobians(jo + 1); val a2 = jacobians(jo + 2)
    if size == 1 then
      val g0 = i00 * a0; val g1 = i00 * a1; val g2 = i00 * a2
      factor(o) = g0; factor(o + 1) = g1; factor(o + 2) = g2
      d(q) -= a0 * g0; d(q + 1) -= a0 * g1; d(q + 2) -= a0 * g2
      d(q + 3) -= a1 * g1; d(q + 4) -= a1 * g2; d(q + 5) -= a2 * g2
      z(qv) -= a0 * y0; z(qv + 1) -= a1 * y0; z(qv + 2) -= a2 * y0
    else
      val b0 = jacobians(jo + 3); val b1 = jacobians(jo + 4); val b2 = jacobians(jo + 5)
      // G = D^-1 J, rows g and h
      val g0 = i00 * a0 + i01 * b0; val g1 = i00 * a1 + i01 * b1; val g2 = i00 * a2 + i01 * b2
      val h0 = i01 * a0 + i11 * b0; val h1 = i01 * a1 + i11 * b1; val h2 = i01 * a2 + i11 * b2
      factor(o) = g0; factor(o + 1) = g1; factor(o + 2) = g2
      factor(o + 3) = h0; factor(o + 4) = h1; factor(o + 5) = h2
      d(q) -= a0 * g0 + b0 * h0; d(q + 1) -= a0 * g1 + b0 * h1; d(q + 2) -= a0 * g2 + b0 * h2
      d(q + 3) -= a1 * g1 + b1 * h1; d(q + 4) -= a1 * g2 + b1 * h2; d(q + 5) -= a2 * g2 + b2 * h2
      z(qv) -= a0 * y0 + b0 * y1; z(qv + 1) -= a1 * y0 + b1 * y1; z(qv + 2) -= a2 * y0 + b2 * y1

  /** The slots `from until until`, roots first: x_c = D_c^-1 (z_c - H_cp x_p) = w_c - (the
    * factor) x_p; then the velocities change by their bodies' x (a folded body's by -M^-1 J^T x
    * of its joints), each joint's accumulated impulse by -x.
    */
  private def substitute(state: Array[Double], fresh: Boolean, from: Int, until: Int): Unit =
    val plan = this.plan; val factor = this.factor; val w = this.w; val x = this.x
    var slot = from
    while slot < until do
      val p = Plan.Stride * slot
      val o = 6 * slot
      val v = 3 * slot
      val size = plan(p + Plan.Size)
      val above = plan(p + Plan.Above)
      if size < 3 then
        val two = size == 2
        if above < 0 then
          x(v) = w(v)
          if two then x(v + 1) = w(v + 1)
        else
          val qv = 3 * above
          val aboveSize = plan(Plan.Stride * above + Plan.Size)
          if aboveSize < 3 then
            // x = w - G x_above
            if !two && aboveSize == 1 then x(v) = w(v) - factor(o) * x(qv)
            else
              val p0 = x(qv); val p1 = if aboveSize == 2 then x(qv + 1) else 0.0
              x(v) = w(v) - (factor(o) * p0 + factor(o + 1) * p1)
              if two then x(v + 1) = w(v + 1) - (factor(o + 2) * p0 + factor(o + 3) * p1)
          else
            // x = w - G x_above
            val p0 = x(qv); val p1 = x(qv + 1); val p2 = x(qv + 2)
            x(v) = w(v) - (factor(o) * p0 + factor(o + 1) * p1 + factor(o + 2) * p2)
            if two then x(v + 1) = w(v + 1) - (factor(o + 3) * p0 + factor(o + 4) * p1 + factor(o + 5) * p2)
        val x0 = x(v); val x1 = if two then x(v + 1) else 0.0
        if fresh then
          accumulated(2 * slot) = -x0
          if two then accumulated(2 * slot + 1) = -x1
        else
          accumulated(2 * slot) -= x0
          if two then accumulated(2 * slot + 1) -= x1
        val folds = plan(p + Plan.Folds)
        val m = 4 * slot
        val j1 = 12 * slot
        if (folds & 1) != 0 then push(state, plan(p + Plan.State1), masses(m), masses(m + 1), j1, two, x0, x1)
        if (folds & 2) != 0 then push(state, plan(p + Plan.State2), masses(m + 2), masses(m + 3), j1 + 6, two, x0, x1)
      else
        if above < 0 then
          x(v) = w(v); x(v + 1) = w(v + 1); x(v + 2) = w(v + 2)
        else
          // x = w - F^T x_p
          val qv = 3 * above
          val q0 = x(qv)
          if plan(Plan.Stride * above + Plan.Size) == 1 then
            x(v) = w(v) - factor(o) * q0
            x(v + 1) = w(v + 1) - factor(o + 1) * q0
            x(v + 2) = w(v + 2) - factor(o + 2) * q0
          else
            val q1 = x(qv + 1)
            x(v) = w(v) - factor(o) * q0 - factor(o + 3) * q1
            x(v + 1) = w(v + 1) - factor(o + 1) * q0 - factor(o + 4) * q1
            x(v + 2) = w(v + 2) - factor(o + 2) * q0 - factor(o + 5) * q1
        val k = plan(p + Plan.State1)
        state(k + VelocityX) += x(v); state(k + VelocityY) += x(v + 1); state(k + AngularVelocity) += x(v + 2)
      slot += 1

  /** A folded body's share of its joint's solution: dv = -M^-1 J^T x, M^-1 its inverse mass m
    * and moment i, its state at `k`, J the joint's rows for the body at `rows` (the second row
    * only when `two`).
    */
  private def push(state: Array[Double], k: Int, m: Double, i: Double, rows: Int, two: Boolean, x0: Double,
      x1: Double): Unit =
    var fx = jacobians(rows) * x0; var fy = jacobians(rows + 1) * x0; var torque = jacobians(rows + 2) * x0
    if two then
      fx += jacobians(rows + 3) * x1; fy += jacobians(rows + 4) * x1; torque += jacobians(rows + 5) * x1
    state(k + VelocityX) -= m * fx; state(k + VelocityY) -= m * fy; state(k + AngularVelocity) -= i * torque

  /** Rows at r and q of a joint's Jacobian for one body through that body's inverse mass: its
    * part of the joint's own effective mass matrix J M^-1 J^T.
    */
  private inline def coupling(r: Int, q: Int, invMass: Double, invI: Double): Double =
    invMass * (jacobians(r) * jacobians(q) + jacobians(r + 1) * jacobians(q + 1)) + invI * jacobians(r + 2) * jacobians(q + 2)

  /** The Jacobian row at `row` times the velocity of the body whose state starts at `s`. */
  private inline def rowVelocity(row: Int, state: Array[Double], s: Int): Double =
    jacobians(row) * state(s + VelocityX) + jacobians(row + 1) * state(s + VelocityY) +
      jacobians(row + 2) * state(s + AngularVelocity)

private[sims] object JointTrees:
  /** The offsets of a slot's plan (see `plan`): Stride entries a slot. */
  private object Plan:
    final val Ref = 0
    final val Size = 1
    final val Above = 2
    final val Block = 3
    final val Over = 4
    final val Folds = 5
    final val State1 = 6
    final val State2 = 7
    final val Stride = 8
  /** The trees' compliance in the solve pass, relative to each joint's own effective mass: it
    * stretches a joint under load by about Compliance g h^2 per unit of the load it carries
    * (0.0002 mm at 4 substeps of 1/60 s), and bounds how far a near-singular tree amplifies an
    * error into velocity.
    */
  val Compliance: Double = 0.001
