package sims.solver

import sims.Defaults
import sims.collision.Contact
import sims.dynamics.{Checked, World}
import sims.solver.soft.{ContactConstraints, SoftBodies, SoftWorkspace}
import sims.solver.soft.SoftBodies.*

/** The soft step: substeps, soft constraints, warm starting, relaxation and
  * speculative contacts, the design Box2D v3 made the field's best for stable stacks, long
  * chains and high mass ratios. Choose it per world: `world.solver = SoftStep()`.
  *
  * One step, its stages in order (each a method below):
  *   1. `advanceTime`
  *   2. `loadBodies`: the bodies' state into flat arrays
  *   3. `findContacts`: broadphase with bounds enlarged by `speculativeDistance`, manifolds
  *      with feature ids, warm starting from the last step's contact of the same shape pair
  *   4. `prepare`: effective masses, softness, the normal velocities before the step
  *   5. `substeps` times: `integrateVelocities` (gravity and forces, the force joints' at the
  *      substep's placements; what they add to the approach of contact points that have not
  *      pushed yet), `warmStart`, `solve` (with bias: joints, contacts, joint trees),
  *      `integratePositions`, `relax` (`solve` without bias)
  *   6. `applyRestitution`, once: every point that pushed after approaching faster than
  *      `restitutionThreshold` bounces from that approach, all such points at once (passes in
  *      turn, at most `Defaults.RestitutionIterations`, until none is off its target by more
  *      than `Defaults.RestitutionTolerance`), so that restitution 1 keeps the kinetic energy
  *   7. `finish`: placements and velocities back into the bodies, forces cleared; the
  *      touching contacts reported to the world's contact events; sleeping (islands of bodies
  *      that rested long enough fall asleep, see [[sims.dynamics.Body.isAwake]]); the contacts
  *      with their impulses kept for the next step
  *   8. bullets (`Body.bullet`) swept against fixed shapes ([[ContinuousCollision]]), in a world
  *      that has them
  *
  * Friction and restitution of a pair are the products of the two shapes' values, as in the
  * classic step; `world.iterations` and `world.enablePositionCorrection` are the classic
  * step's settings and are not used here.
  *
  * @param substeps substeps per `world.timeStep` (at least 1)
  * @param contactHertz stiffness of contacts, Hz; used at most 0.25 / substep
  * @param contactDampingRatio damping ratio of contacts
  * @param staticContactFactor contacts with a fixed body use `contactHertz` times this
  * @param jointHertz stiffness of rigid joints, Hz; used at most 0.25 / substep
  * @param jointDampingRatio damping ratio of rigid joints
  * @param contactSpeed the fastest that overlap is pushed apart, m/s
  * @param restitutionThreshold impacts slower than this do not bounce, m/s
  * @param linearSlop overlap tolerance of the narrowphase's choices, m
  * @param speculativeDistance contact points are made this far before shapes touch, m
  * @param contactPersistence a contact's manifold is kept (not computed again) while its bodies
  *   moved less than this relative to each other since it was computed, m; 0 computes every step
  * @param contactLoadDepth a contact whose load would press it deeper than this is stiffened
  *   (up to 0.25 / substep, and not softened again while it lasts), m; 0 keeps every contact at
  *   `contactHertz`
  * @param directJoints whether joints that form trees (chains, ragdolls) are solved exactly by
  *   the linear-time direct solver, as rigid constraints; otherwise every joint is solved by
  *   soft Gauss-Seidel sweeps with `jointHertz`, as in Box2D v3
  * @param gridSide side of the broadphase's grid cells, m (the world's one broadphase, which the
  *   classic step uses with its detector's `gridSide`)
  * @param maxPairs the most candidate pairs a step may have; a step with more fails, changing
  *   nothing, with an IllegalStateException naming this limit (the pairs kept from step to step,
  *   whose bounds are enlarged by a tenth, may number twice as many)
  * @param workers how many threads share a step's contacts and bodies (the caller and
  *   `workers - 1` others, kept in a pool; none is started for 1); the results are the same, to
  *   the bit, for any number (default: the available processors; 1 on Scala.js)
  */
final case class SoftStep(
    substeps: Int = Defaults.Substeps,
    contactHertz: Double = Defaults.ContactHertz,
    contactDampingRatio: Double = Defaults.ContactDampingRatio,
    staticContactFactor: Double = Defaults.StaticContactFactor,
    jointHertz: Double = Defaults.JointHertz,
    jointDampingRatio: Double = Defaults.JointDampingRatio,
    contactSpeed: Double = Defaults.ContactSpeed,
    restitutionThreshold: Double = Defaults.RestitutionThreshold,
    linearSlop: Double = Defaults.LinearSlop,
    speculativeDistance: Double = Defaults.SpeculativeDistance,
    contactPersistence: Double = Defaults.ContactPersistence,
    contactLoadDepth: Double = Defaults.ContactLoadDepth,
    directJoints: Boolean = true,
    gridSide: Double = Defaults.GridSide,
    maxPairs: Int = Defaults.MaxCandidatePairs,
    workers: Int = Workers.available) extends Solver:
  if substeps < 1 then throw IllegalArgumentException(s"substeps must be at least 1, got $substeps")
  SoftStep.requirePositive("contactHertz", contactHertz)
  SoftStep.requireNonNegative("contactDampingRatio", contactDampingRatio)
  SoftStep.requirePositive("staticContactFactor", staticContactFactor)
  SoftStep.requirePositive("jointHertz", jointHertz)
  SoftStep.requireNonNegative("jointDampingRatio", jointDampingRatio)
  SoftStep.requirePositive("contactSpeed", contactSpeed)
  SoftStep.requireNonNegative("restitutionThreshold", restitutionThreshold)
  SoftStep.requirePositive("linearSlop", linearSlop)
  SoftStep.requireNonNegative("speculativeDistance", speculativeDistance)
  SoftStep.requireNonNegative("contactPersistence", contactPersistence)
  SoftStep.requireNonNegative("contactLoadDepth", contactLoadDepth)
  SoftStep.requirePositive("gridSide", gridSide)
  if maxPairs < 1 then throw IllegalArgumentException(s"maxPairs must be at least 1, got $maxPairs")
  if workers < 1 then throw IllegalArgumentException(s"workers must be at least 1, got $workers")

  // The worker set, made at the first step (a world that never steps starts no thread).
  private lazy val pool: Workers = Workers(workers)

  def step(world: World): Unit =
    val workspace = world.workspace(classOf[SoftWorkspace], SoftWorkspace())
    val h = world.timeStep / substeps
    val bullets = world.bulletCount > 0
    if bullets then bulletsOf(world).begin(world)
    // world.stage names the stage under way for the error of a failed step.
    world.stage = "advanceTime"
    advanceTime(world)
    world.stage = "loadBodies"
    loadBodies(world, workspace, h)
    if resting(world, workspace) then
      // Every body sleeps (or is fixed), and nothing changed: the step moves nothing, and the
      // contacts, and so the pairs touching, stay as they are.
      world.stage = "finish"
      world.contactTracker.touchAllOpen()
      workspace.islands.update(world, workspace.bodies, workspace.table.committed, world.jointList)
      return
    world.stage = "findContacts"
    findContacts(world, workspace)
    world.stage = "prepare"
    prepare(world, workspace, h)
    var substep = 0
    while substep < substeps do
      world.stage = "integrateVelocities"
      // The first substep checks the forces and velocities before the contacts spread a
      // non-finite velocity to other bodies (NaN on a fixed one): the exact checks, which name
      // the body, only when a range's sum is not finite.
      if !integrateVelocities(world, workspace, h, check = substep == 0) then
        world.guard("joint forces", Checked.Forces)
        val failed = workspace.bodies.firstNonFiniteVelocity()
        if failed >= 0 then world.guardFailure(failed, "integrateVelocities", Checked.Velocities)
      world.stage = "warmStart"
      warmStart(workspace)
      world.stage = "solve"
      solve(workspace, useBias = true, exactTrees = true)
      world.stage = "integratePositions"
      integratePositions(workspace, h)
      world.stage = "relax"
      solve(workspace, useBias = false, exactTrees = substep == substeps - 1) // relax
      substep += 1
    world.stage = "applyRestitution"
    applyRestitution(world, workspace, h)
    world.stage = "finish"
    finish(world, workspace)
    if bullets then
      world.stage = "continuous collision"
      bulletsOf(world).sweep(world)
      world.guard("continuous collision", Checked.Positions)

  /** Every parameter by name, e.g. `SoftStep(substeps = 4, contactHertz = 30.0, ...)`; `workers`
    * only when it is not the default (the machine's processors: it changes no result).
    */
  override def toString: String =
    productElementNames.zip(productIterator)
      .filterNot((name, value) => name == "workers" && value == Workers.available)
      .map((name, value) => s"$name = $value").mkString("SoftStep(", ", ", ")")

  /** The soft step reports the contacts that touch itself (see [[sims.solver.soft.ContactTouching]]). */
  override private[sims] def reportsTouching: Boolean = true

  /** The soft step saves the bodies' state as it loads them (see [[sims.solver.soft.SoftBodies.loadRange]]). */
  override private[sims] def savesBodies: Boolean = true

  /** The soft step judges the open pairs not touched in ranges, on its workers (see
    * [[sims.solver.soft.SoftPasses.settleEvents]]).
    */
  override private[sims] def finishContactEvents(world: World): Unit =
    world.workspace(classOf[SoftWorkspace], SoftWorkspace()).passes.settleEvents(pool, world)

  private def bulletsOf(world: World): ContinuousCollision =
    world.workspace(classOf[ContinuousCollision], ContinuousCollision())

  /** A substep: the force joints' forces are applied in every substep. */
  override def forceInterval(world: World): Double = world.timeStep / substeps

  /** The contacts of the last soft step, speculative ones included: points where they are after
    * the step, separations after the step's motion.
    */
  def contacts(world: World): IndexedSeq[Contact] =
    world.workspace(classOf[SoftWorkspace], SoftWorkspace()).contactViews()

  private def advanceTime(world: World): Unit = world.advanceTime()

  private def loadBodies(world: World, workspace: SoftWorkspace, h: Double): Unit =
    val bodies = workspace.bodies
    workspace.passes.load(pool, world.bodyList, world.stateBeforeStep, h)
    if bodies.anyAsleep then wakeJointed(world, bodies)
    workspace.joints.sort(world, bodies, directJoints)

  /** Wakes the sleeping islands jointed to an awake body that moves (a joint made since they
    * fell asleep, or a partner woken by the user) or to a body outside the world, until none is.
    */
  private def wakeJointed(world: World, bodies: SoftBodies): Unit =
    val joints = world.jointList
    var woke = true
    while woke do
      woke = false
      var j = 0
      while j < joints.length do
        val a = joints(j).node1.index
        val b = joints(j).node2.index
        // A joint to a body outside the world (a mouse joint's target) keeps its body awake.
        val sleeper =
          if a < 0 || b < 0 then (if a >= 0 && bodies.asleep(a) then a else if b >= 0 && bodies.asleep(b) then b else -1)
          else if bodies.asleep(a) && bodies.invMass(b) != 0 then a
          else if bodies.asleep(b) && bodies.invMass(a) != 0 then b
          else -1
        if sleeper >= 0 then
          bodies.wakeIsland(bodies.bodies(sleeper).sleepIsland)
          woke = true
        j += 1

  /** Whether the step has nothing to do: every body asleep or fixed, no fixed body placed by the
    * user, no kinematic body moving, collision detection on, no body or joint added or removed since the last step that
    * collided its pairs, whose contacts are still the committed ones.
    */
  private def resting(world: World, workspace: SoftWorkspace): Boolean =
    val bodies = workspace.bodies
    if !bodies.anyAsleep || !world.enableCollisionDetection || workspace.collidedRevision != world.revision ||
      world.bulletCount > 0 then false
    else
      var i = 0
      while i < bodies.count && bodies.invMass(i) == 0 && !bodies.bodies(i).movedByUser &&
        !bodies.bodies(i).movesItself do i += 1
      i == bodies.count

  private def findContacts(world: World, workspace: SoftWorkspace): Unit =
    if world.enableCollisionDetection then
      workspace.finder.find(world, workspace.table, workspace.bodies, pool, gridSide, maxPairs, speculativeDistance, linearSlop,
        contactPersistence)
    else workspace.table.begin()

  private def prepare(world: World, workspace: SoftWorkspace, h: Double): Unit =
    val rate = 1 / h
    val table = workspace.table
    // The carried softness of stiffened contacts is used again only if worked out for the same substep and damping.
    val reuses = table.committed.stiffenedH == h && table.committed.stiffenedZeta == contactDampingRatio
    workspace.stiffness.set(contactHertz, 0.25 * rate, contactDampingRatio, staticContactFactor, contactLoadDepth, h,
      reuses)
    table.current.stiffenedH = h
    table.current.stiffenedZeta = contactDampingRatio
    workspace.passes.prepare(pool, world.gravity.x, world.gravity.y)
    val context = workspace.context
    context.bodies = workspace.bodies
    context.h = h
    context.inverseH = rate
    context.jointSoftness.set(math.min(jointHertz, 0.25 * rate), jointDampingRatio, h)
    val joints = workspace.joints.constraints
    var i = 0
    while i < joints.length do
      joints(i).prepare(context)
      i += 1
    workspace.joints.trees.markTouched(workspace.table.current, workspace.bodies)

  /** Gravity and forces: v += h (g + F/m), w += h tau/I for every moving body; the force
    * joints' forces are computed from the substep's placements and velocities. With `check`,
    * whether every body's forces and velocities are finite (else true).
    */
  private def integrateVelocities(world: World, workspace: SoftWorkspace, h: Double, check: Boolean): Boolean =
    val bodies = workspace.bodies
    if workspace.joints.forceJoints.nonEmpty then applyForceJoints(workspace)
    val gx = world.gravity.x
    val gy = world.gravity.y
    val finite = workspace.passes.integrateVelocities(pool, gx, gy, h, check)
    ContactConstraints.addFreeMotion(workspace.table.current, bodies, gx, gy, h)
    finite

  /** The force joints' forces at the substep's placements and velocities, added to the user's. */
  private def applyForceJoints(workspace: SoftWorkspace): Unit =
    val bodies = workspace.bodies
    val touched = workspace.joints.forceBodies
    var t = 0
    while t < touched.length do
      val i = touched(t)
      bodies.expose(i)
      val b = bodies.bodies(i)
      b.fx = bodies.forceX(i); b.fy = bodies.forceY(i); b.tau = bodies.torque(i)
      t += 1
    val joints = workspace.joints.forceJoints
    var j = 0
    while j < joints.length do
      joints(j).applyForce()
      j += 1
    t = 0
    while t < touched.length do
      val i = touched(t)
      val b = bodies.bodies(i)
      bodies.substepForceX(i) = b.fx; bodies.substepForceY(i) = b.fy; bodies.substepTorque(i) = b.tau
      t += 1

  /** Applies the impulses accumulated so far: joints', then contacts'. */
  private def warmStart(workspace: SoftWorkspace): Unit =
    val trees = workspace.joints.trees
    trees.warmStart(workspace.context)
    val joints = trees.iterative
    var i = 0
    while i < joints.length do
      joints(i).warmStart(workspace.context)
      i += 1
    workspace.passes.warmStart(pool)

  /** One pass over the constraints, with the bias (solve) or without (relax): a soft
    * Gauss-Seidel sweep over the joints outside trees, then over the contacts, then the joint
    * trees solved exactly ([[sims.solver.soft.joints.JointTrees]]). Unless `exactTrees`, a
    * relax pass leaves alone the trees nothing else acts on (no contact, no joint solved
    * iteratively, no limit, motor or spring): the next solve pass sets their rows' velocities to
    * their targets whatever they were, so solving them here would change nothing that lasts. The
    * last relax pass solves every tree, so that the step ends with every joint of a tree at
    * rest along its rows.
    */
  private def solve(workspace: SoftWorkspace, useBias: Boolean, exactTrees: Boolean): Unit =
    val trees = workspace.joints.trees
    val joints = trees.iterative
    var i = 0
    while i < joints.length do
      joints(i).solve(workspace.context, useBias)
      i += 1
    workspace.passes.solve(pool, workspace.context.inverseH, contactSpeed, useBias)
    // The trees last: their exact solve leaves every joint of a tree exact at the end of the
    // pass, where a contact solved after it would pull a pin open (measured: a ragdoll landing
    // opened its pins by up to 13 mm with the trees first, 1.3 mm with them last).
    trees.solve(workspace.context, useBias, always = exactTrees)

  /** dp += h v, dAngle += h w, and the turns' cosines and sines (see [[SoftPasses]]). */
  private def integratePositions(workspace: SoftWorkspace, h: Double): Unit =
    workspace.passes.integratePositions(pool, h)

  private def applyRestitution(world: World, workspace: SoftWorkspace, h: Double): Unit =
    ContactConstraints.restitution(workspace.table.current, workspace.bodies, restitutionThreshold,
      Defaults.RestitutionIterations, Defaults.RestitutionTolerance, world.gravity.x, world.gravity.y, h)

  private def finish(world: World, workspace: SoftWorkspace): Unit =
    val finite = workspace.passes.finish(pool, world)
    workspace.joints.trees.storeImpulses()
    val joints = workspace.joints.constraints
    var i = 0
    while i < joints.length do
      joints(i).report(workspace.context.inverseH)
      i += 1
    if !finite then
      // The guard names the first body that is not finite, and fails the step.
      world.guard("soft step substeps", Checked.Velocities)
      world.guard("soft step substeps", Checked.Positions)
    workspace.passes.close(pool, world)
    workspace.table.commit()
    workspace.collidedRevision = if world.enableCollisionDetection then world.revision else -1

/** Checks of [[SoftStep]]'s parameters. */
object SoftStep:
  private def requirePositive(name: String, value: Double): Unit =
    if !(value > 0) || value.isInfinite then
      throw IllegalArgumentException(s"$name must be positive and finite, got $value")

  private def requireNonNegative(name: String, value: Double): Unit =
    if !(value >= 0) || value.isInfinite then
      throw IllegalArgumentException(s"$name must be finite and at least 0, got $value")
