package sims.solver.soft

import sims.solver.soft.ContactTable.*
import sims.solver.soft.SoftBodies.*

/** The soft step's contact constraints (see docs/two-solvers.md), over the arrays of a
  * [[Contacts]] generation and of [[SoftBodies]].
  *
  * Derivation, per point with arms rA, rB from the bodies' centres at the start of the step,
  * normal n (from A to B) and tangent t = n.leftNormal:
  *   C     = s, the separation, >= 0; during the substeps s = s0 + n . (dB(point) - dA(point))
  *           with d(point) = dp + R(dAngle) r - r the point's displacement since the start
  *           (R(dAngle) = 1 for a turnless side, `Contacts.turnless`: a circle on its body's
  *           centre, whose arm lies along n, so that r x n = 0 and no turn moves its outline
  *           along n, or a fixed body)
  *   Cdot  = vn = n . (vB + wB x rB - vA - wA x rA)
  *   K     = 1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB     (its inverse: the normal mass)
  *   lambda = -normalMass massScale (vn + bias) - impulseScale lambdaAcc, then lambdaAcc >= 0
  * with the bias and scales of the soft rule: s > 0 (speculative) pushes only what would
  * close the gap within the substep (bias s / h, rigid); an overlap is pushed out softly, at
  * most `contactSpeed` fast (softer still where that cap binds, `DeepMassScale`), in the solve
  * pass, and not at all in the relax pass. Friction:
  * lambdaT = -tangentMass vt, the accumulated value within [-mu lambdaAcc, mu lambdaAcc].
  */
private[sims] object ContactConstraints:

  /** The mass scale (and 1 - it the impulse scale) of a point overlapping so deeply that its
    * push is capped at `contactSpeed`. With the contact's own softness, two such pushes that
    * balance (a body jammed between two fixed shapes, or held inside one by a joint) each
    * accumulate normalMass contactSpeed massScale / impulseScale, 16 to 73 times normalMass
    * contactSpeed at the defaults (30 to 120 Hz); when one side lets go (new feature ids, the
    * body turning) the other's warm start flings the body at that many times contactSpeed.
    * Half and half bound the balance at normalMass contactSpeed, what one push alone may give.
    * No load reaches this depth: it would take at least 1,200 g per unit of effective mass.
    */
  inline val DeepMassScale = 0.5

  /** Computes, for contacts `from` until `until`, what stays fixed during the step: their
    * effective masses, the normal relative velocity before the step, and the softness (stiffer
    * against fixed bodies, and stiffened under a heavy load, see [[ContactStiffness]]). The arms
    * and separations are the collision stage's; the bodies' inverse masses, the passes read from
    * [[ContactBlocks]]' places.
    */
  def prepare(contacts: Contacts, bodies: SoftBodies, stiffness: ContactStiffness, from: Int, until: Int): Unit =
    val hot = contacts.hot
    val cold = contacts.cold
    val state = bodies.state
    val records = contacts.records
    var c = from
    while c < until do
      val a = contacts.bodyA(c)
      val b = contacts.bodyB(c)
      val mA = bodies.invMass(a); val iA = bodies.invI(a)
      val mB = bodies.invMass(b); val iB = bodies.invI(b)

      val k = contacts.offset(c)
      val nx = hot(k + NormalX); val ny = hot(k + NormalY)
      val tx = -ny; val ty = nx
      val sA = a * SoftBodies.Stride; val sB = b * SoftBodies.Stride
      val turnless = contacts.turnless(c) == Turnless
      var p = 0
      while p < contacts.pointCount(c) do
        val q = contacts.hotPoint(c, p)
        val rAx = hot(q + AnchorAX); val rAy = hot(q + AnchorAY)
        val rBx = hot(q + AnchorBX); val rBy = hot(q + AnchorBY)
        val separation = cold(contacts.coldPoint(c, p) + Separation)
        val kNormal =
          if turnless then
            // No turn on either side: no moment about the normal, and no outline moved along it.
            hot(q + BaseSeparation) = separation
            mA + mB
          else
            hot(q + BaseSeparation) = separation - ((rBx - rAx) * nx + (rBy - rAy) * ny)
            val rnA = rAx * ny - rAy * nx; val rnB = rBx * ny - rBy * nx
            mA + mB + iA * rnA * rnA + iB * rnB * rnB
        hot(q + NormalMass) = if kNormal > 0 then 1 / kNormal else 0
        val rtA = rAx * ty - rAy * tx; val rtB = rBx * ty - rBy * tx
        val kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB
        hot(q + TangentMass) = if kTangent > 0 then 1 / kTangent else 0
        val r = contacts.recordPoint(c, p)
        records(r + MaxNormalImpulse) = 0
        hot(q + TotalNormalImpulse) = 0
        records(r + ImpactGap) = 0
        val dvx = state(sB + VelocityX) - state(sB + AngularVelocity) * rBy - state(sA + VelocityX) + state(sA + AngularVelocity) * rAy
        val dvy = state(sB + VelocityY) + state(sB + AngularVelocity) * rBx - state(sA + VelocityY) - state(sA + AngularVelocity) * rAx
        records(r + RelativeVelocity) = dvx * nx + dvy * ny
        p += 1
      stiffness.set(contacts, c, mA == 0 || mB == 0)
      c += 1

  /** Applies the accumulated impulses (from the last step, then from the substeps) of the
    * contacts at places `from until until` (see [[ContactBlocks]]).
    */
  def warmStart(contacts: Contacts, bodies: SoftBodies, blocks: ContactBlocks, from: Int, until: Int): Unit =
    val hot = contacts.hot
    val places = blocks.places
    val masses = blocks.placeMasses
    val state = bodies.state
    var n = from
    while n < until do
      val place = ContactBlocks.PlaceStride * n
      val c = places(place)
      if contacts.turnless(c) == Turnless then n = warmStartTurnless(contacts, state, blocks, n, until)
      else
        val sA = places(place + 1)
        val sB = places(place + 2)
        val mA = masses(4 * n); val iA = masses(4 * n + 1)
        val mB = masses(4 * n + 2); val iB = masses(4 * n + 3)
        var vAx = state(sA + VelocityX); var vAy = state(sA + VelocityY); var wA = state(sA + AngularVelocity)
        var vBx = state(sB + VelocityX); var vBy = state(sB + VelocityY); var wB = state(sB + AngularVelocity)
        val k = places(place + 3)
        val nx = hot(k + NormalX); val ny = hot(k + NormalY)
        val two = contacts.pointCount(c) == 2
        var q = k + Header
        var p = 0
        while p == 0 || (p == 1 && two) do
          val normal = hot(q + NormalImpulse)
          val tangent = hot(q + TangentImpulse)
          // n normal + t tangent, t = n.leftNormal = (-ny, nx)
          val px = nx * normal - ny * tangent
          val py = ny * normal + nx * tangent
          vAx -= px * mA; vAy -= py * mA; wA -= (hot(q + AnchorAX) * py - hot(q + AnchorAY) * px) * iA
          vBx += px * mB; vBy += py * mB; wB += (hot(q + AnchorBX) * py - hot(q + AnchorBY) * px) * iB
          q += HotPoint
          p += 1
        state(sA + VelocityX) = vAx; state(sA + VelocityY) = vAy; state(sA + AngularVelocity) = wA
        state(sB + VelocityX) = vBx; state(sB + VelocityY) = vBy; state(sB + AngularVelocity) = wB
        n += 1

  /** `warmStart` for the run of contacts from place `from` on, while each is turnless on both
    * sides (see `solveTurnless`), up to `until`; returns where the run ends. Its one point's
    * normal impulse acts along both arms and turns neither body (as in the passes, which give
    * it no turn); the tangent impulse turns them by the arms' moments about the tangent.
    */
  private def warmStartTurnless(contacts: Contacts, state: Array[Double], blocks: ContactBlocks, from: Int,
      until: Int): Int =
    val hot = contacts.hot
    val places = blocks.places
    val masses = blocks.placeMasses
    val turnless = contacts.turnless
    var n = from
    while n < until && turnless(places(ContactBlocks.PlaceStride * n)) == Turnless do
      val place = ContactBlocks.PlaceStride * n
      val sA = places(place + 1)
      val sB = places(place + 2)
      val mA = masses(4 * n); val iA = masses(4 * n + 1)
      val mB = masses(4 * n + 2); val iB = masses(4 * n + 3)
      val k = places(place + 3)
      val nx = hot(k + NormalX); val ny = hot(k + NormalY)
      val q = k + Header
      val normal = hot(q + NormalImpulse)
      val tangent = hot(q + TangentImpulse)
      val px = nx * normal - ny * tangent
      val py = ny * normal + nx * tangent
      // The arms' moments about the tangent, as the relax pass's friction has them.
      val tx = -ny; val ty = nx
      val rtA = hot(q + AnchorAX) * ty - hot(q + AnchorAY) * tx
      val rtB = hot(q + AnchorBX) * ty - hot(q + AnchorBY) * tx
      state(sA + VelocityX) -= px * mA; state(sA + VelocityY) -= py * mA
      state(sA + AngularVelocity) -= tangent * iA * rtA
      state(sB + VelocityX) += px * mB; state(sB + VelocityY) += py * mB
      state(sB + AngularVelocity) += tangent * iB * rtB
      n += 1
    n

  /** One pass over the contacts at places `from until until` (see [[ContactBlocks]]): normal
    * impulses (with the soft bias when `useBias`, the solve pass; without, the relax pass), then,
    * in the relax pass, friction.
    *
    * The pass waits on a chain, from one impulse to the next point's velocity along its row,
    * more than on its arithmetic, so what does not depend on the velocities is worked out apart
    * from them: the arms' moments about the normal (r x n) and the tangent, the turn a unit
    * impulse gives each body, and the new accumulated impulse as base - slope v. A contact's
    * second point sees its first point's impulse through their coupling, 1/mA + 1/mB +
    * (rA0 x n)(rA1 x n) / IA + (rB0 x n)(rB1 x n) / IB, the change that impulse makes to its
    * velocity, and the bodies take both impulses at once: Gauss-Seidel over the points as
    * before, with a chain half as long. A contact turnless on both sides takes a shorter way
    * (`solveTurnless`).
    */
  def solve(contacts: Contacts, bodies: SoftBodies, blocks: ContactBlocks, from: Int, until: Int, inverseH: Double,
      contactSpeed: Double, useBias: Boolean): Unit =
    val hot = contacts.hot
    val places = blocks.places
    val masses = blocks.placeMasses
    val state = bodies.state
    val bouncing = contacts.bouncing
    val records = contacts.records
    var n = from
    while n < until do
      val place = ContactBlocks.PlaceStride * n
      val c = places(place)
      val turnless = contacts.turnless(c)
      if turnless == Turnless then n = solveTurnless(contacts, state, blocks, n, until, inverseH, contactSpeed, useBias)
      else
        val sA = places(place + 1)
        val sB = places(place + 2)
        val mA = masses(4 * n); val iA = masses(4 * n + 1)
        val mB = masses(4 * n + 2); val iB = masses(4 * n + 3)
        var vAx = state(sA + VelocityX); var vAy = state(sA + VelocityY); var wA = state(sA + AngularVelocity)
        var vBx = state(sB + VelocityX); var vBy = state(sB + VelocityY); var wB = state(sB + AngularVelocity)
        // B's displacement relative to A's since the step began, and their turns: the points'
        // current separations.
        val dpx = state(sB + ShiftX) - state(sA + ShiftX)
        val dpy = state(sB + ShiftY) - state(sA + ShiftY)
        var cosA = state(sA + TurnCos); var sinA = state(sA + TurnSin)
        var cosB = state(sB + TurnCos); var sinB = state(sB + TurnSin)
        if turnless != 0 then // a circle on a moving body: its turn moves no outline along the normal
          if (turnless & TurnlessA) != 0 then { cosA = 1.0; sinA = 0.0 }
          if (turnless & TurnlessB) != 0 then { cosB = 1.0; sinB = 0.0 }
        val k = places(place + 3)
        val nx = hot(k + NormalX); val ny = hot(k + NormalY)
        val mAnx = mA * nx; val mAny = mA * ny; val mBnx = mB * nx; val mBny = mB * ny
        val q0 = k + Header
        val s0 = separationAt(hot, q0, nx, ny, dpx, dpy, cosA, sinA, cosB, sinB)
        val rnA0 = hot(q0 + AnchorAX) * ny - hot(q0 + AnchorAY) * nx
        val rnB0 = hot(q0 + AnchorBX) * ny - hot(q0 + AnchorBY) * nx
        val turnA0 = iA * rnA0; val turnB0 = iB * rnB0
        val vn0 = ((vBx - vAx) * nx + (vBy - vAy) * ny) + (wB * rnB0 - wA * rnA0)
        val impulse0 = solveNormal(hot, k, q0, s0, vn0, inverseH, contactSpeed, useBias, bouncing, records, c, 0)
        val two = contacts.pointCount(c) == 2
        if !two then
          vAx -= impulse0 * mAnx; vAy -= impulse0 * mAny; wA -= impulse0 * turnA0
          vBx += impulse0 * mBnx; vBy += impulse0 * mBny; wB += impulse0 * turnB0
        else
          val q1 = q0 + HotPoint
          val s1 = separationAt(hot, q1, nx, ny, dpx, dpy, cosA, sinA, cosB, sinB)
          val rnA1 = hot(q1 + AnchorAX) * ny - hot(q1 + AnchorAY) * nx
          val rnB1 = hot(q1 + AnchorBX) * ny - hot(q1 + AnchorBY) * nx
          val turnA1 = iA * rnA1; val turnB1 = iB * rnB1
          val coupling = (mA + mB) + (turnA0 * rnA1 + turnB0 * rnB1)
          val vn1 = (((vBx - vAx) * nx + (vBy - vAy) * ny) + (wB * rnB1 - wA * rnA1)) + coupling * impulse0
          val impulse1 = solveNormal(hot, k, q1, s1, vn1, inverseH, contactSpeed, useBias, bouncing, records, c, 1)
          val both = impulse0 + impulse1
          vAx -= both * mAnx; vAy -= both * mAny; wA -= impulse0 * turnA0 + impulse1 * turnA1
          vBx += both * mBnx; vBy += both * mBny; wB += impulse0 * turnB0 + impulse1 * turnB1
        // Friction, in the relax pass only (as in Box2D v3; solving it in the solve pass too
        // measured no better on the stack, pyramid and ball-pit scenes), bounded by the normal
        // impulses just found.
        if !useBias then
          val tx = -ny; val ty = nx
          val friction = hot(k + Friction)
          val mAtx = mA * tx; val mAty = mA * ty; val mBtx = mB * tx; val mBty = mB * ty
          val rtA0 = hot(q0 + AnchorAX) * ty - hot(q0 + AnchorAY) * tx
          val rtB0 = hot(q0 + AnchorBX) * ty - hot(q0 + AnchorBY) * tx
          val turnA0 = iA * rtA0; val turnB0 = iB * rtB0
          val vt0 = ((vBx - vAx) * tx + (vBy - vAy) * ty) + (wB * rtB0 - wA * rtA0)
          val impulse0 = solveFriction(hot, q0, friction, vt0)
          if !two then
            vAx -= impulse0 * mAtx; vAy -= impulse0 * mAty; wA -= impulse0 * turnA0
            vBx += impulse0 * mBtx; vBy += impulse0 * mBty; wB += impulse0 * turnB0
          else
            val q1 = q0 + HotPoint
            val rtA1 = hot(q1 + AnchorAX) * ty - hot(q1 + AnchorAY) * tx
            val rtB1 = hot(q1 + AnchorBX) * ty - hot(q1 + AnchorBY) * tx
            val turnA1 = iA * rtA1; val turnB1 = iB * rtB1
            val coupling = (mA + mB) + (turnA0 * rtA1 + turnB0 * rtB1)
            val vt1 = (((vBx - vAx) * tx + (vBy - vAy) * ty) + (wB * rtB1 - wA * rtA1)) + coupling * impulse0
            val impulse1 = solveFriction(hot, q1, friction, vt1)
            val both = impulse0 + impulse1
            vAx -= both * mAtx; vAy -= both * mAty; wA -= impulse0 * turnA0 + impulse1 * turnA1
            vBx += both * mBtx; vBy += both * mBty; wB += impulse0 * turnB0 + impulse1 * turnB1
        state(sA + VelocityX) = vAx; state(sA + VelocityY) = vAy; state(sA + AngularVelocity) = wA
        state(sB + VelocityX) = vBx; state(sB + VelocityY) = vBy; state(sB + AngularVelocity) = wB
        n += 1

  /** `solve` for the run of contacts from place `from` on, while each is turnless on both
    * sides (two circles on their bodies' centres, or such a circle and a fixed body; every
    * contact of a ball pit), up to `until`; returns where the run ends. Such a contact has one
    * point, its normal row neither reads nor changes the bodies' spin, and its separation is
    * the bodies' approach alone (an arm turned with a circle would move its outline off the
    * point: a spinning ball would seem to part from what it rests on). A method of its own, its
    * loop a run rather than one contact a call: the general loop's code already holds as many
    * inlined calls as the compiler allows, and HotSpot would not inline one contact's code,
    * too long, into it either.
    */
  private def solveTurnless(contacts: Contacts, state: Array[Double], blocks: ContactBlocks, from: Int, until: Int,
      inverseH: Double, contactSpeed: Double, useBias: Boolean): Int =
    val hot = contacts.hot
    val places = blocks.places
    val masses = blocks.placeMasses
    val turnless = contacts.turnless
    val bouncing = contacts.bouncing
    val records = contacts.records
    var n = from
    while n < until && turnless(places(ContactBlocks.PlaceStride * n)) == Turnless do
      val place = ContactBlocks.PlaceStride * n
      val c = places(place)
      val sA = places(place + 1)
      val sB = places(place + 2)
      val mA = masses(4 * n); val mB = masses(4 * n + 2)
      var vAx = state(sA + VelocityX); var vAy = state(sA + VelocityY)
      var vBx = state(sB + VelocityX); var vBy = state(sB + VelocityY)
      val k = places(place + 3)
      val nx = hot(k + NormalX); val ny = hot(k + NormalY)
      val q = k + Header
      val s = (state(sB + ShiftX) - state(sA + ShiftX)) * nx + (state(sB + ShiftY) - state(sA + ShiftY)) * ny +
        hot(q + BaseSeparation)
      val vn = (vBx - vAx) * nx + (vBy - vAy) * ny
      val impulse = solveNormal(hot, k, q, s, vn, inverseH, contactSpeed, useBias, bouncing, records, c, 0)
      // Products written left to right (see `solveNormal`).
      vAx -= impulse * mA * nx; vAy -= impulse * mA * ny
      vBx += impulse * mB * nx; vBy += impulse * mB * ny
      if !useBias then
        // Friction, as for any one-point contact.
        val iA = masses(4 * n + 1); val iB = masses(4 * n + 3)
        var wA = state(sA + AngularVelocity); var wB = state(sB + AngularVelocity)
        val tx = -ny; val ty = nx
        val rtA = hot(q + AnchorAX) * ty - hot(q + AnchorAY) * tx
        val rtB = hot(q + AnchorBX) * ty - hot(q + AnchorBY) * tx
        val vt = ((vBx - vAx) * tx + (vBy - vAy) * ty) + (wB * rtB - wA * rtA)
        val friction = solveFriction(hot, q, hot(k + Friction), vt)
        vAx -= friction * mA * tx; vAy -= friction * mA * ty; wA -= friction * iA * rtA
        vBx += friction * mB * tx; vBy += friction * mB * ty; wB += friction * iB * rtB
        state(sA + AngularVelocity) = wA; state(sB + AngularVelocity) = wB
      state(sA + VelocityX) = vAx; state(sA + VelocityY) = vAy
      state(sB + VelocityX) = vBx; state(sB + VelocityY) = vBy
      n += 1
    n

  /** The current separation of the point at q, normal (nx, ny), from its bodies' motion since the
    * step began: B's displacement relative to A's (dpx, dpy) and each body's turn (cosine, sine).
    */
  private inline def separationAt(hot: Array[Double], q: Int, nx: Double, ny: Double, dpx: Double, dpy: Double,
      cosA: Double, sinA: Double, cosB: Double, sinB: Double): Double =
    val rAx = hot(q + AnchorAX); val rAy = hot(q + AnchorAY)
    val rBx = hot(q + AnchorBX); val rBy = hot(q + AnchorBY)
    val dx = dpx + (cosB * rBx - sinB * rBy) - (cosA * rAx - sinA * rAy)
    val dy = dpy + (sinB * rBx + cosB * rBy) - (sinA * rAx + cosA * rAy)
    dx * nx + dy * ny + hot(q + BaseSeparation)

  /** The normal impulse of point p at q of contact c (its hot block at k), separation s, normal
    * velocity vn: the soft rule's (see the object's comment), accumulated and clamped at 0, and
    * the records restitution needs (in `records`); returns the impulse to apply.
    */
  private inline def solveNormal(hot: Array[Double], k: Int, q: Int, s: Double, vn: Double, inverseH: Double,
      contactSpeed: Double, useBias: Boolean, bouncing: Boolean, records: Array[Double], c: Int, p: Int): Double =
    val accumulated = hot(q + NormalImpulse)
    val normalMass = hot(q + NormalMass)
    var slope = normalMass
    var base = accumulated
    // Speculative: may close the gap, no more. (Written left to right: the JavaScript
    // bundle's minifier prints a * (b * c) as a * b * c, which rounds differently.)
    if s > 0 then base -= s * inverseH * normalMass
    else if useBias then
      val bias = hot(k + BiasRate) * s
      if bias >= -contactSpeed then
        slope = normalMass * hot(k + MassScale)
        base = accumulated - hot(k + ImpulseScale) * accumulated - slope * bias
      else
        // Deeper than the push's cap: see DeepMassScale.
        slope = normalMass * DeepMassScale
        base = accumulated - (1 - DeepMassScale) * accumulated + slope * contactSpeed
    // A branch rather than math.max, whose rules for NaN and signed zeros stood in the chain:
    // the same value (NaN kept, a negative zero to 0).
    val raw = base - slope * vn
    val total = if raw <= 0 then 0.0 else raw
    val impulse = total - accumulated
    hot(q + NormalImpulse) = total
    // A substep applies its accumulated impulse in all (warm start, solve, relax): at the
    // end of its relax pass, this is what it applied.
    if !useBias then hot(q + TotalNormalImpulse) += total
    // For restitution (a contact that bounces only): the largest push, and the first push's
    // gap: positive when a solve pass pushed (the gap at the start of the substep it meets
    // in), negative when a relax pass did (its gap after the substep's positions: it meets
    // in the next substep), 0 when the bodies touched already.
    if bouncing then
      val r = c * RecordStride + RecordHeader + p * RecordPoint
      val strongest = records(r + MaxNormalImpulse)
      if s > 0 && impulse > 0 && strongest == 0 then records(r + ImpactGap) = if useBias then s else -s
      if impulse > strongest then records(r + MaxNormalImpulse) = impulse
    impulse

  /** The friction impulse of the point at q, tangential velocity vt, within the friction
    * coefficient times its normal impulse (branches, as in `solveNormal`); returns the impulse to apply.
    */
  private inline def solveFriction(hot: Array[Double], q: Int, friction: Double, vt: Double): Double =
    val accumulated = hot(q + TangentImpulse)
    val bound = friction * hot(q + NormalImpulse)
    val raw = accumulated - hot(q + TangentMass) * vt
    val total = if raw > bound then bound else if raw < -bound then -bound else raw
    hot(q + TangentImpulse) = total
    total - accumulated

  /** Adds to each point's approach what the substep's gravity and forces (`integrateVelocities`)
    * changed of its normal velocity, while the point has not pushed yet this step: its approach
    * at impact, for restitution, is the one at the start of the step plus what gravity and
    * forces added before it (a ball falling onto the ground: the speed it hits with), and none
    * of what other contacts did to the bodies within the step (see `restitution`).
    */
  def addFreeMotion(contacts: Contacts, bodies: SoftBodies, gx: Double, gy: Double, h: Double): Unit =
    val records = contacts.records
    var c = 0
    while contacts.bouncing && c < contacts.active do
      if records(c * RecordStride + Restitution) != 0 then
        var p = 0
        while p < contacts.pointCount(c) do
          val q = contacts.hotPoint(c, p)
          val r = contacts.recordPoint(c, p)
          if records(r + MaxNormalImpulse) == 0 then
            records(r + RelativeVelocity) += freeAlongNormal(contacts, c, q, bodies, gx, gy, h)
          p += 1
      c += 1

  /** The current separation of contact c's point at q, from the motion of its bodies (their state
    * in `state`) since the step began.
    */
  def separationNow(contacts: Contacts, c: Int, q: Int, state: Array[Double]): Double =
    val hot = contacts.hot
    val k = contacts.offset(c)
    val sA = contacts.bodyA(c) * SoftBodies.Stride
    val sB = contacts.bodyB(c) * SoftBodies.Stride
    val nx = hot(k + NormalX); val ny = hot(k + NormalY)
    val dpx = state(sB + ShiftX) - state(sA + ShiftX)
    val dpy = state(sB + ShiftY) - state(sA + ShiftY)
    val turnless = contacts.turnless(c)
    if turnless == Turnless then dpx * nx + dpy * ny + hot(q + BaseSeparation)
    else
      val turnsA = (turnless & TurnlessA) == 0; val turnsB = (turnless & TurnlessB) == 0
      separationAt(hot, q, nx, ny, dpx, dpy, if turnsA then state(sA + TurnCos) else 1.0,
        if turnsA then state(sA + TurnSin) else 0.0, if turnsB then state(sB + TurnCos) else 1.0,
        if turnsB then state(sB + TurnSin) else 0.0)

  /** Where contact c's point at q is now, on body A: its arm from A's centre, turned with A
    * unless that side is turnless (a circle's point stays on the line from its centre along the
    * normal, however the circle turns).
    */
  def pointNow(contacts: Contacts, c: Int, q: Int, bodies: SoftBodies): sims.geometry.Vector2D =
    val hot = contacts.hot
    val state = bodies.state
    val a = contacts.bodyA(c)
    val sA = a * SoftBodies.Stride
    val turns = (contacts.turnless(c) & TurnlessA) == 0
    val cos = if turns then state(sA + TurnCos) else 1.0
    val sin = if turns then state(sA + TurnSin) else 0.0
    val rx = hot(q + AnchorAX); val ry = hot(q + AnchorAY)
    sims.geometry.Vector2D(bodies.startX(a) + state(sA + ShiftX) + (cos * rx - sin * ry),
      bodies.startY(a) + state(sA + ShiftY) + (sin * rx + cos * ry))

  /** The change of the normal velocity of contact c's point at q over a substep h by gravity
    * and the forces alone.
    */
  private def freeAlongNormal(contacts: Contacts, c: Int, q: Int, bodies: SoftBodies, gx: Double, gy: Double,
      h: Double): Double =
    val hot = contacts.hot
    val k = contacts.offset(c)
    val a = contacts.bodyA(c)
    val b = contacts.bodyB(c)
    val mA = bodies.invMass(a); val mB = bodies.invMass(b)
    val sA = bodies.gravityScale(a); val sB = bodies.gravityScale(b)
    val dvAx = if mA == 0 then 0.0 else h * (gx * sA + bodies.substepForceX(a) * mA)
    val dvAy = if mA == 0 then 0.0 else h * (gy * sA + bodies.substepForceY(a) * mA)
    val dwA = h * bodies.substepTorque(a) * bodies.invI(a)
    val dvBx = if mB == 0 then 0.0 else h * (gx * sB + bodies.substepForceX(b) * mB)
    val dvBy = if mB == 0 then 0.0 else h * (gy * sB + bodies.substepForceY(b) * mB)
    val dwB = h * bodies.substepTorque(b) * bodies.invI(b)
    val nx = hot(k + NormalX); val ny = hot(k + NormalY)
    val dvx = dvBx - dwB * hot(q + AnchorBY) - dvAx + dwA * hot(q + AnchorAY)
    val dvy = dvBy + dwB * hot(q + AnchorBX) - dvAy - dwA * hot(q + AnchorAX)
    dvx * nx + dvy * ny

  /** Once per step, after the substeps: the points that were approaching faster than
    * `threshold` (see `addFreeMotion`) and pushed during the step bounce, their normal
    * velocities set to -e times their approach, all at once: Gauss-Seidel passes over them
    * (impulses clamped as always) until no point is off its target by more than `tolerance`,
    * m/s, or after `iterations` passes.
    *
    * Why all at once and from the approach before the substeps: the substeps stopped each
    * impact (a plastic collision, its impulse P pressing where the bodies approached), so the
    * velocities after them are u = u0 + M^-1 J^T P with J u = 0 at the pushing points, u0 the
    * velocities at the start. Setting every J u = -e J u0 at once then applies e P once more,
    * and the kinetic energy after is that before minus (1 - e^2) times the energy the plastic
    * collision took: none lost for e = 1, none ever gained. One pass in turn does not reach it
    * where a body is in two impacts (the second bounce undoes part of the first), and an
    * approach measured within the substeps (after other contacts pushed the bodies, or
    * inflated by warm starting) is no longer J u0: both gained energy (docs/two-solvers.md).
    */
  def restitution(contacts: Contacts, bodies: SoftBodies, threshold: Double, iterations: Int, tolerance: Double,
      gx: Double, gy: Double, h: Double): Unit =
    val hot = contacts.hot
    val records = contacts.records
    val state = bodies.state
    var pass = 0
    var largest = Double.PositiveInfinity
    while contacts.bouncing && pass < iterations && largest > tolerance do
      largest = 0.0
      var c = 0
      while c < contacts.active do
        val k = contacts.offset(c)
        val e = records(c * RecordStride + Restitution)
        if e != 0 then
          val a = contacts.bodyA(c)
          val b = contacts.bodyB(c)
          val sA = a * SoftBodies.Stride; val sB = b * SoftBodies.Stride
          val nx = hot(k + NormalX); val ny = hot(k + NormalY)
          var p = 0
          while p < contacts.pointCount(c) do
            val q = k + Header + p * HotPoint
            val r = contacts.recordPoint(c, p)
            if records(r + RelativeVelocity) < -threshold && records(r + MaxNormalImpulse) > 0 then
              val rAx = hot(q + AnchorAX); val rAy = hot(q + AnchorAY)
              val rBx = hot(q + AnchorBX); val rBy = hot(q + AnchorBY)
              val dvx = state(sB + VelocityX) - state(sB + AngularVelocity) * rBy - state(sA + VelocityX) +
                state(sA + AngularVelocity) * rAy
              val dvy = state(sB + VelocityY) + state(sB + AngularVelocity) * rBx - state(sA + VelocityY) -
                state(sA + AngularVelocity) * rAx
              val vn = dvx * nx + dvy * ny
              val accumulated = hot(q + NormalImpulse)
              // The substeps move positions by the velocity at each substep's end: under a
              // steady pull f per substep along the normal (gravity, forces; f < 0 pulls the
              // two together) a body moves as it would in continuous time at a speed half an f
              // behind. A fall meets in the substep whose velocity u is its approach (the one
              // after a relax pass's first push: u = approach + f) at a fraction phi of that
              // substep's travel (the gap then over h |u|): the motion's own impact speed is
              // c = -u - f (phi - 1/2). The bounce sends it back at e c from the surface, or at
              // what is left of e c at the gap g it turned at (a push at the step's last relax
              // pass), plus half an f for the rise's own lag: vn = sqrt((e c)^2 + 2 f g / h) - f / 2.
              // Bouncing at -e u instead lost up to a substep's travel of height at every
              // bounce (1.8% of a 1 m drop at e = 1); without gravity and forces it is -e u.
              val free = freeAlongNormal(contacts, c, q, bodies, gx, gy, h)
              val recorded = records(r + ImpactGap)
              val impact = if recorded < 0 then records(r + RelativeVelocity) + free else records(r + RelativeVelocity)
              val phi = if impact < 0 then math.min(1.0, math.abs(recorded) / (-impact * h)) else 0.0
              val speed = -impact - free * (phi - 0.5)
              val gap = math.max(0.0, separationNow(contacts, c, q, bodies.state))
              val launch = math.sqrt(math.max(0.0, e * e * speed * speed + 2 * free / h * gap)) - 0.5 * free
              val target = -launch
              val total = math.max(accumulated - hot(q + NormalMass) * (vn + target), 0.0)
              val impulse = total - accumulated
              if impulse != 0 then
                // How far the point was from its target (or from where the clamp stops it).
                val off = math.abs(impulse) / hot(q + NormalMass)
                if off > largest then largest = off
                hot(q + NormalImpulse) = total
                hot(q + TotalNormalImpulse) += impulse
                bodies.applyImpulse(a, -impulse * nx, -impulse * ny, rAx, rAy)
                bodies.applyImpulse(b, impulse * nx, impulse * ny, rBx, rBy)
            p += 1
        c += 1
      pass += 1
