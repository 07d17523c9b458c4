package sims.solver

import sims.Defaults
import sims.collision.{Collision, Contact}
import sims.dynamics.{Checked, World}
import sims.dynamics.joints.ForceJoint

/** SiMS 1.2's time step, the default solver: the seven phases of SiMS 1.2 (documentation
  * 3.3 and 4.10), in order, each a method below:
  *
  *   1. `advanceTime`: time += h
  *   2. `applyJointForces`: every ForceJoint applies its force
  *   3. `integrateAccelerations`: gravity, then v += F/m h and w += tau/I h
  *   4. `correctVelocities`: the detector finds the collisions; `iterations` times every
  *      joint's, then every collision's `correctVelocity` (collisions through [[ContactSolver]])
  *   5. `integrateVelocities`: resting speeds become 0; x += v h, rotation += w h; forces cleared
  *   6. `correctPositions`: `iterations` times every joint's, then every collision's
  *      `correctPosition`, the narrowphase rerun before each pass
  *   7. the world's post-step hook (run by the world)
  *
  * Results are SiMS's rules to the bit; how they are computed (flat arrays, wave order) is
  * free (deviation 6). Beside SiMS's phases, two stages that change nothing in
  * a world without bullets: the pairs that touch are reported to the world's contact events
  * (`reportTouching`, after phase 4's detection and after phase 6), and bullets are swept
  * against fixed shapes at the end ([[ContinuousCollision]]).
  */
object ClassicStep extends Solver:
  def step(world: World): Unit =
    val h = world.timeStep
    val bullets = world.bulletCount > 0
    if bullets then bulletsOf(world).begin(world)
    world.stage = "advance time"
    advanceTime(world) // phase 1
    world.stage = "joint forces"
    applyJointForces(world) // phase 2
    world.guard("joint forces", Checked.Forces)
    world.stage = "integration of accelerations"
    integrateAccelerations(world, h) // phase 3
    world.guard("integration of accelerations", Checked.Velocities)
    world.stage = "velocity correction"
    correctVelocities(world, h) // phase 4
    world.guard("velocity correction", Checked.Velocities)
    world.stage = "integration of velocities"
    integrateVelocities(world, h) // phase 5
    world.guard("integration of velocities", Checked.Positions)
    if world.enablePositionCorrection then
      world.stage = "position correction"
      correctPositions(world, h) // phase 6
      world.guard("position correction", Checked.Positions)
      if world.enableCollisionDetection then reportTouching(world)
    if bullets then
      world.stage = "continuous collision"
      bulletsOf(world).sweep(world)
      world.guard("continuous collision", Checked.Positions)

  override def toString: String = "ClassicStep"

  /** The classic step reports the pairs that touch itself (see `reportTouching`). */
  override private[sims] def reportsTouching: Boolean = true

  private def bulletsOf(world: World): ContinuousCollision =
    world.workspace(classOf[ContinuousCollision], ContinuousCollision())

  /** The detector's collisions after the last position correction: each point with the
    * separation -overlap of the shapes along the normal, impulses 0 (the classic step keeps none).
    * None when the last classic step did not detect collisions (`enableCollisionDetection`
    * off): the detector's collisions are then an earlier step's, and their pairs' events ended.
    */
  def contacts(world: World): IndexedSeq[Contact] =
    if !world.workspace(classOf[ContactSolver], ContactSolver()).detected then IndexedSeq.empty
    else
      world.detector.collisions.iterator.map { c =>
        val points = c.points.toIndexedSeq
        val separation = -Collision.overlapAlong(c.shape1, c.shape2, c.normal.x, c.normal.y)
        val zeros = IndexedSeq.fill(points.length)(0.0)
        Contact(c.shape1, c.shape2, c.normal, points, IndexedSeq.fill(points.length)(separation), zeros, zeros, zeros)
      }.toIndexedSeq

  private def advanceTime(world: World): Unit = world.advanceTime()

  private def applyJointForces(world: World): Unit =
    val joints = world.jointList
    var i = 0
    while i < joints.length do
      joints(i) match
        case f: ForceJoint => f.applyForce()
        case _ => ()
      i += 1

  private def integrateAccelerations(world: World, h: Double): Unit =
    val bodies = world.bodyList
    val gx = world.gravity.x
    val gy = world.gravity.y
    var i = 0
    while i < bodies.length do
      val b = bodies(i)
      if !b.immovable then
        val m = b.mass
        // Times the gravity scale, 1 unless the user set it: exact, SiMS's sums unchanged.
        b.fx += gx * m * b.gravityScale
        b.fy += gy * m * b.gravityScale
        b.vx += (b.fx / m) * h
        b.vy += (b.fy / m) * h
        b.w += (b.tau / b.I) * h
        if b.damped then damp(b, h)
      i += 1

  /** The body's damping over one step (an extension of SiMS): v / (1 + h linearDamping),
    * w / (1 + h angularDamping), the implicit form that never reverses a velocity.
    */
  private def damp(b: sims.dynamics.Body, h: Double): Unit =
    val linear = 1 / (1 + h * b.linearDamping)
    b.vx *= linear
    b.vy *= linear
    b.w *= 1 / (1 + h * b.angularDamping)

  private def correctVelocities(world: World, h: Double): Unit =
    val contacts = world.workspace(classOf[ContactSolver], ContactSolver())
    contacts.detected = world.enableCollisionDetection
    if world.enableCollisionDetection then
      world.detector.detect()
      reportTouching(world) // before the velocities change: the approach speeds of new pairs
      contacts.load(world.detector.collisions)
    else contacts.clear()
    val joints = world.jointList
    var iteration = 0
    while iteration < world.iterations do
      var i = 0
      while i < joints.length do
        joints(i).correctVelocity(h)
        i += 1
      contacts.correctVelocities(h)
      iteration += 1

  /** Reports the detector's collisions with points to the world's contact events: a pair that
    * touches now and did not before begins, with the collision's normal, the middle of its
    * points and its approach speed (the fastest closing speed along the normal among its
    * points, from the velocities as they are now).
    */
  private def reportTouching(world: World): Unit =
    if world.enableContactEvents then reportTouchingPairs(world)

  private def reportTouchingPairs(world: World): Unit =
    val collisions = world.detector.collisions
    val tracker = world.contactTracker
    var i = 0
    while i < collisions.length do
      val c = collisions(i)
      c.load()
      if c.pointCount > 0 && tracker.touch(c.shape1, c.shape2) then describe(c, tracker)
      i += 1

  private def describe(c: Collision, tracker: sims.collision.PairTracker): Unit =
    val b1 = c.shape1.body
    val b2 = c.shape2.body
    val nx = c.normalX
    val ny = c.normalY
    var sumX, sumY = 0.0
    var approach = 0.0
    var p = 0
    while p < c.pointCount do
      val px = c.pointX(p)
      val py = c.pointY(p)
      sumX += px
      sumY += py
      // v2(p) - v1(p) along n: negative while the shapes close in.
      val dvx = b2.vx - b2.w * (py - b2.y) - b1.vx + b1.w * (py - b1.y)
      val dvy = b2.vy + b2.w * (px - b2.x) - b1.vy - b1.w * (px - b1.x)
      approach = math.max(approach, -(dvx * nx + dvy * ny))
      p += 1
    tracker.describe(nx, ny, sumX / c.pointCount, sumY / c.pointCount, approach, 0)

  private def integrateVelocities(world: World, h: Double): Unit =
    val bodies = world.bodyList
    var i = 0
    while i < bodies.length do
      val b = bodies(i)
      if math.sqrt(b.vx * b.vx + b.vy * b.vy) < Defaults.RestingSpeed then
        b.vx = 0; b.vy = 0
      if math.abs(b.w) < Defaults.RestingSpeed then b.w = 0
      b.displace(b.vx * h, b.vy * h, b.w * h)
      b.fx = 0; b.fy = 0; b.tau = 0
      i += 1

  private def correctPositions(world: World, h: Double): Unit =
    val joints = world.jointList
    var iteration = 0
    while iteration < world.iterations do
      var i = 0
      while i < joints.length do
        joints(i).correctPosition(h)
        i += 1
      if world.enableCollisionDetection then
        world.detector.refresh()
        val collisions = world.detector.collisions
        i = 0
        while i < collisions.length do
          collisions(i).correctPosition(h)
          i += 1
      iteration += 1
