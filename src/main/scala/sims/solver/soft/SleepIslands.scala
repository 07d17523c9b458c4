package sims.solver.soft

import sims.Defaults
import sims.dynamics.World

/** The soft step's sleeping (see docs/two-solvers.md, Sleeping), after the bodies got their new state: each
  * awake body's resting time grows while it is slower than its `sleepThreshold` (its centre's
  * speed, and its extent times its angular speed) and starts again from 0 when it is not; then,
  * once some body has rested for `Defaults.TimeToSleep`, the awake bodies are joined into
  * islands by this step's contacts and joints (fixed bodies join nothing), and every island
  * whose bodies have all rested that long falls asleep: velocities 0, one island number for all.
  * Islands are found again each time, so a body that left an island (its contact ended) is
  * no longer held awake by it. The order is the bodies' and contacts': the same bits each run.
  */
private[sims] final class SleepIslands:
  // Union-find over the bodies' indices: parent, and per root the least resting time.
  private var parent = new Array[Int](0)
  private var least = new Array[Double](0)
  private var island = new Array[Long](0)

  /** Updates the resting times and puts the islands that rested long enough to sleep. */
  def update(world: World, bodies: SoftBodies, contacts: Contacts, joints: collection.IndexedSeq[sims.dynamics.joints.Joint]): Unit =
    if rest(world, bodies, 0, bodies.count) then sleep(world, bodies, contacts, joints)

  /** Updates the resting times of bodies `from` until `until` (and forgets that the user placed
    * them); whether one of them has rested long enough to sleep. Writes those bodies only: ranges
    * may rest on several threads at once.
    */
  def rest(world: World, bodies: SoftBodies, from: Int, until: Int): Boolean =
    val dt = world.timeStep
    val sleepOn = world.enableSleep
    var ready = false
    var i = from
    while i < until do
      val b = bodies.bodies(i)
      b.movedByUser = false
      if bodies.invMass(i) != 0 then
        val threshold = b.sleepThreshold
        val speed2 = b.vx * b.vx + b.vy * b.vy
        val turn = b.extent * b.w
        if !sleepOn || !b.enableSleep || speed2 > threshold * threshold || turn * turn > threshold * threshold ||
          threshold == 0 then b.sleepTime = 0
        else
          b.sleepTime += dt
          if b.sleepTime >= Defaults.TimeToSleep then ready = true
      i += 1
    ready

  /** Joins the awake bodies into islands by `contacts` and `joints`, and puts every island whose
    * bodies have all rested long enough to sleep (after `rest` said one has).
    */
  def sleep(world: World, bodies: SoftBodies, contacts: Contacts,
      joints: collection.IndexedSeq[sims.dynamics.joints.Joint]): Unit =
    val n = bodies.count
    if parent.length < n then
      parent = new Array[Int](n); least = new Array[Double](n); island = new Array[Long](n)
    var i = 0
    while i < n do
      parent(i) = i
      i += 1
    var c = 0
    while c < contacts.active do
      join(bodies, contacts.bodyA(c), contacts.bodyB(c))
      c += 1
    var j = 0
    while j < joints.length do
      val joint = joints(j)
      join(bodies, joint.node1.index, joint.node2.index)
      j += 1
    i = 0
    while i < n do
      least(i) = Double.PositiveInfinity
      island(i) = -1
      i += 1
    i = 0
    while i < n do
      if bodies.invMass(i) != 0 then
        val r = root(i)
        least(r) = math.min(least(r), bodies.bodies(i).sleepTime)
      i += 1
    i = 0
    while i < n do
      if bodies.invMass(i) != 0 then
        val r = root(i)
        if least(r) >= Defaults.TimeToSleep then
          if island(r) < 0 then island(r) = world.newSleepIsland()
          bodies.bodies(i).fallAsleep(island(r))
      i += 1

  /** Joins the islands of bodies a and b if both are awake and move. */
  private def join(bodies: SoftBodies, a: Int, b: Int): Unit =
    if a >= 0 && b >= 0 && bodies.invMass(a) != 0 && bodies.invMass(b) != 0 then
      val ra = root(a)
      val rb = root(b)
      // The smaller index is the root: the same islands, numbered in the same order, each run.
      if ra < rb then parent(rb) = ra else if rb < ra then parent(ra) = rb

  private def root(i: Int): Int =
    var r = i
    while parent(r) != r do r = parent(r)
    var k = i
    while parent(k) != r do
      val next = parent(k)
      parent(k) = r
      k = next
    r
