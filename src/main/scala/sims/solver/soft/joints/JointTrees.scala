package sims.solver.soft.joints

import scala.collection.mutable.ArrayBuffer
import sims.solver.ShortCopy
import sims.solver.soft.{SmallMatrix, SoftBodies, SoftContext}
import sims.solver.soft.SoftBodies.*

/** The soft step's direct solver for joints that form trees (a chain, a pendulum, a ragdoll):
  * in every pass it solves all the tree's joint rows at once, exactly, in time linear in the
  * number of joints (Baraff 1996, "Linear-time dynamics using Lagrange multipliers"), where
  * one Gauss-Seidel sweep per pass would pass a correction along a 100-link chain only one
  * link per sweep. Its joints are rigid: the solve pass removes the whole position error C
  * within the substep (bias C / h), with a small compliance that keeps a tree near a singular
  * pose from amplifying that bias without bound (see `setUp`); the relax pass is exact and
  * takes the bias velocity out again.
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
  * 3 x 3. Joints in loops (nets, trusses) and joints that give no rows (the mouse joint, a
  * user's) stay with the iterative soft solver.
  */
private[sims] final class JointTrees:
  /** The joints of this step left to the iterative solver, in world order. */
  val iterative: ArrayBuffer[JointConstraint] = ArrayBuffer.empty[JointConstraint]
  private val direct = ArrayBuffer.empty[JointConstraint]
  private val rows = JointRows()
  // Per direct joint t: its moving bodies (-1 when fixed), its bodies' indices (fixed ones
  // too: a fixed body may move at a given velocity), rows, Jacobians (k x 3 each) and errors.
  private var body1, body2, index1, index2, rowCount = new Array[Int](0)
  private var jacobian1, jacobian2 = new Array[Double](0)
  private var positionError = new Array[Double](0)
  // The elimination tree, nodes in breadth-first order from each root: kind (body or joint),
  // the body index or joint number, size and parent node (-1 for a root).
  private var nodeCount = 0
  private var nodeIsJoint = new Array[Boolean](0)
  private var nodeRef, nodeSize, nodeParent = new Array[Int](0)
  // Per node, 3 x 3 blocks (row-major, stride 3): D, its inverse, and the Jacobian block
  // between the node and its parent (k x 3: the joint's rows for the body).
  private var d, dInverse, jacobian = new Array[Double](0)
  private var z, x = new Array[Double](0)
  // Scratch of one elimination.
  private val y = new Array[Double](2)
  private val g = new Array[Double](9)
  // Graph building.
  private var unionParent, bodyJoints, groundJoints, touched = new Array[Int](0)
  private var bodyNode = new Array[Int](0)
  // Each body's incident direct joints: incident(start(b) until start(b + 1)).
  private var start, incident, filled = new Array[Int](0)
  private var jointSeen = new Array[Boolean](0)

  /** Sorts this step's constraint joints into trees (solved here) and the rest. */
  def build(joints: ArrayBuffer[JointConstraint], bodies: SoftBodies): Unit =
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
      if constraint.directRows > 0 && some >= 0 && bodyJoints(find(some)) == 1 && groundJoints(find(some)) <= 1 then
        direct += constraint
      else iterative += constraint
      j += 1
    layOut(bodies)

  /** Leaves every joint to the iterative solver. */
  def keepIterative(joints: ArrayBuffer[JointConstraint]): Unit =
    direct.clear()
    iterative.clear()
    iterative ++= joints
    nodeCount = 0

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
      jacobian1 = new Array[Double](12 * joints); jacobian2 = new Array[Double](12 * joints)
      positionError = new Array[Double](4 * joints)
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
      nodeIsJoint = new Array[Boolean](capacity)
      nodeRef = new Array[Int](capacity); nodeSize = new Array[Int](capacity); nodeParent = new Array[Int](capacity)
      d = new Array[Double](9 * capacity); dInverse = new Array[Double](9 * capacity)
      jacobian = new Array[Double](9 * capacity)
      z = new Array[Double](3 * capacity); x = new Array[Double](3 * capacity)
    java.util.Arrays.fill(bodyNode, 0, n, -1)
    if jointSeen.length < joints then jointSeen = new Array[Boolean](2 * joints)
    java.util.Arrays.fill(jointSeen, 0, joints, false)
    nodeCount = 0
    // Trees held by a joint to the ground grow from that joint; free trees from their lowest body.
    t = 0
    while t < joints do
      if (body1(t) < 0 || body2(t) < 0) && !jointSeen(t) then
        jointSeen(t) = true
        grow(addNode(isJoint = true, t, rowCount(t), -1))
      t += 1
    i = 0
    while i < n do
      if start(i + 1) > start(i) && bodyNode(i) < 0 then
        bodyNode(i) = addNode(isJoint = false, i, 3, -1)
        grow(nodeCount - 1)
      i += 1

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
    nodeCount += 1
    node

  /** Applies the direct joints' accumulated impulses (the exact solve does not need them to
    * converge, but the contacts solved before it in a pass see the joints' load).
    */
  def warmStart(context: SoftContext): Unit =
    var t = 0
    while t < direct.length do
      direct(t).warmStart(context)
      t += 1

  /** One exact pass over every tree: with the bias C / h (`useBias`) or without. */
  def solve(context: SoftContext, useBias: Boolean): Unit =
    if direct.nonEmpty then
      val state = context.bodies.state
      // The rows the trees leave to Gauss-Seidel (limits, motors, springs) first, as a joint
      // solved iteratively does before its own point constraint.
      var t = 0
      while t < direct.length do
        direct(t).solveAxial(context, useBias)
        t += 1
      t = 0
      while t < direct.length do
        direct(t).rowsAt(context, rows)
        ShortCopy.doubles(rows.jacobian1, 0, jacobian1, 6 * t, 6)
        ShortCopy.doubles(rows.jacobian2, 0, jacobian2, 6 * t, 6)
        positionError(2 * t) = rows.positionError(0)
        positionError(2 * t + 1) = rows.positionError(1)
        t += 1
      setUp(context, state, useBias)
      eliminate()
      substitute()
      // Velocities change by dv; each joint's accumulated impulse by -y.
      var node = 0
      while node < nodeCount do
        if nodeIsJoint(node) then
          val accumulated = direct(nodeRef(node)).impulse
          var r = 0
          while r < nodeSize(node) do
            accumulated(r) -= x(3 * node + r)
            r += 1
        else
          val k = nodeRef(node) * SoftBodies.Stride
          state(k + VelocityX) += x(3 * node); state(k + VelocityY) += x(3 * node + 1); state(k + AngularVelocity) += x(3 * node + 2)
        node += 1

  /** The blocks of H, the right side, and each node's Jacobian block with its parent (k x 3,
    * row-major: a joint's rows for that body), in `jacobian(node)`.
    */
  private def setUp(context: SoftContext, state: Array[Double], useBias: Boolean): Unit =
    val bodies = context.bodies
    var node = 0
    while node < nodeCount do
      val o = 9 * node
      if nodeIsJoint(node) then
        val joint = nodeRef(node)
        val k = rowCount(joint)
        // A compliance G = Compliance K in the solve pass, K the joint's own effective mass
        // matrix (its two bodies alone): J dv + Cdot + C / h + G (acc + dLambda) = 0, so D = -G
        // and G acc on the right; the relax pass is exact (G = 0, no bias). Exact with bias, a
        // tree near a singular pose (a light body between two links pulled straight) has a
        // near-singular Schur complement and turned an error of centimetres into a velocity
        // of km/s, which a contact solved in the same pass handed to a ball as momentum
        // (kinetic energy up 2.7-fold in zero gravity); with G a joint's response to its error
        // stays within about 1 / Compliance times what its own bodies alone would give.
        val compliance = if useBias then JointTrees.Compliance else 0.0
        val accumulated = direct(joint).impulse
        var r = 0
        while r < k do
          var q = 0
          while q < k do
            d(o + 3 * r + q) =
              if compliance == 0 then 0.0
              else
                -compliance *
                  (rowCoupling(joint, r, q, index1(joint), jacobian1, bodies) +
                    rowCoupling(joint, r, q, index2(joint), jacobian2, bodies))
            q += 1
          r += 1
        r = 0
        while r < k do
          val cdot = rowVelocity(joint, r, state, index1(joint), jacobian1) + rowVelocity(joint, r, state, index2(joint), jacobian2)
          val bias = if useBias then positionError(2 * joint + r) * context.inverseH else 0.0
          var held = 0.0
          var q = 0
          while q < k do
            held -= d(o + 3 * r + q) * accumulated(q)
            q += 1
          z(3 * node + r) = -(cdot + bias + held)
          r += 1
        val parent = nodeParent(node)
        if parent >= 0 then
          val side = if body1(joint) == nodeRef(parent) then jacobian1 else jacobian2
          ShortCopy.doubles(side, 6 * joint, jacobian, o, 6)
      else
        val b = nodeRef(node)
        val mass = 1 / bodies.invMass(b)
        d(o) = mass; d(o + 1) = 0; d(o + 2) = 0
        d(o + 3) = 0; d(o + 4) = mass; d(o + 5) = 0
        d(o + 6) = 0; d(o + 7) = 0; d(o + 8) = 1 / bodies.invI(b)
        z(3 * node) = 0; z(3 * node + 1) = 0; z(3 * node + 2) = 0
        val parent = nodeParent(node)
        if parent >= 0 then
          val joint = nodeRef(parent)
          val side = if body1(joint) == b then jacobian1 else jacobian2
          ShortCopy.doubles(side, 6 * joint, jacobian, o, 6)
      node += 1

  /** Leaves first: each node's D is final once its children are eliminated; it is inverted and
    * eliminated into its parent: D_p -= H_pc D_c^-1 H_cp and z_p -= H_pc D_c^-1 z_c, where H_pc
    * is J^T (3 x k) for a joint below a body and J (k x 3) for a body below a joint.
    */
  private def eliminate(): Unit =
    var node = nodeCount - 1
    while node >= 0 do
      val o = 9 * node
      val parent = nodeParent(node)
      if nodeIsJoint(node) then
        val k = nodeSize(node)
        SmallMatrix.invert(d, o, k, dInverse, o)
        if parent >= 0 then
          val p = 9 * parent
          // y = D^-1 z (k), G = D^-1 J (k x 3)
          var r = 0
          while r < k do
            y(r) = dInverse(o + 3 * r) * z(3 * node) + (if k > 1 then dInverse(o + 3 * r + 1) * z(3 * node + 1) else 0.0)
            var j = 0
            while j < 3 do
              g(3 * r + j) = dInverse(o + 3 * r) * jacobian(o + j) +
                (if k > 1 then dInverse(o + 3 * r + 1) * jacobian(o + 3 + j) else 0.0)
              j += 1
            r += 1
          // D_p -= J^T G, z_p -= J^T y
          var i = 0
          while i < 3 do
            var j = 0
            while j < 3 do
              var sum = jacobian(o + i) * g(j)
              if k > 1 then sum += jacobian(o + 3 + i) * g(3 + j)
              d(p + 3 * i + j) -= sum
              j += 1
            var sum = jacobian(o + i) * y(0)
            if k > 1 then sum += jacobian(o + 3 + i) * y(1)
            z(3 * parent + i) -= sum
            i += 1
      else
        SmallMatrix.invert(d, o, 3, dInverse, o)
        if parent >= 0 then
          val p = 9 * parent
          val k = nodeSize(parent)
          // F = J D^-1 (k x 3); D_p -= F J^T, z_p -= F z
          var r = 0
          while r < k do
            var j = 0
            while j < 3 do
              g(3 * r + j) = jacobian(o + 3 * r) * dInverse(o + j) + jacobian(o + 3 * r + 1) * dInverse(o + 3 + j) +
                jacobian(o + 3 * r + 2) * dInverse(o + 6 + j)
              j += 1
            r += 1
          r = 0
          while r < k do
            var q = 0
            while q < k do
              d(p + 3 * r + q) -= g(3 * r) * jacobian(o + 3 * q) + g(3 * r + 1) * jacobian(o + 3 * q + 1) +
                g(3 * r + 2) * jacobian(o + 3 * q + 2)
              q += 1
            z(3 * parent + r) -= g(3 * r) * z(3 * node) + g(3 * r + 1) * z(3 * node + 1) + g(3 * r + 2) * z(3 * node + 2)
            r += 1
      node -= 1

  /** Roots first: x_c = D_c^-1 (z_c - H_cp x_p). */
  private def substitute(): Unit =
    var node = 0
    while node < nodeCount do
      val o = 9 * node
      val n = nodeSize(node)
      val parent = nodeParent(node)
      if parent >= 0 then
        val xp = 3 * parent
        if nodeIsJoint(node) then
          // z -= J x_p (k)
          var r = 0
          while r < n do
            z(3 * node + r) -= jacobian(o + 3 * r) * x(xp) + jacobian(o + 3 * r + 1) * x(xp + 1) + jacobian(o + 3 * r + 2) * x(xp + 2)
            r += 1
        else
          // z -= J^T x_p (3), J being the parent joint's k x 3 rows
          val k = nodeSize(parent)
          var i = 0
          while i < 3 do
            var sum = jacobian(o + i) * x(xp)
            if k > 1 then sum += jacobian(o + 3 + i) * x(xp + 1)
            z(3 * node + i) -= sum
            i += 1
      SmallMatrix.multiply(dInverse, o, n, z, 3 * node, x, 3 * node)
      node += 1

  /** Rows r and q of the joint's Jacobian for one body through that body's inverse mass:
    * its part of the joint's own effective mass matrix J M^-1 J^T.
    */
  private def rowCoupling(joint: Int, r: Int, q: Int, body: Int, jacobian: Array[Double], bodies: SoftBodies): Double =
    val a = 6 * joint + 3 * r
    val b = 6 * joint + 3 * q
    bodies.invMass(body) * (jacobian(a) * jacobian(b) + jacobian(a + 1) * jacobian(b + 1)) +
      bodies.invI(body) * jacobian(a + 2) * jacobian(b + 2)

  /** Row r of the joint's Jacobian for one body times that body's velocity. */
  private def rowVelocity(joint: Int, r: Int, state: Array[Double], body: Int, jacobian: Array[Double]): Double =
    val k = body * SoftBodies.Stride
    val o = 6 * joint + 3 * r
    jacobian(o) * state(k + VelocityX) + jacobian(o + 1) * state(k + VelocityY) + jacobian(o + 2) * state(k + AngularVelocity)

private[sims] object JointTrees:
  /** The trees' compliance in the solve pass, relative to each joint's own effective mass: it
    * stretches a joint under load by about Compliance g h^2 per unit of the load it carries
    * (0.0002 mm at 4 substeps of 1/60 s), and bounds how far a near-singular tree amplifies an
    * error into velocity.
    */
  val Compliance: Double = 0.001
