package sims.solver.soft

import sims.solver.soft.ContactTable.*

/** The softness of each contact for one step. A contact is as stiff as `hertz` (twice that
  * against a fixed body, `staticFactor`), by default, except where its load would press
  * it deeper: a soft contact carrying the force F between bodies of effective mass m settles F /
  * (m omega^2) into the overlap, so a light box under a heavy one sinks in (a box 100 times
  * heavier on two light ones: 11 cm at 30 Hz). Such a contact is made stiff enough to hold its
  * load within `loadDepth` (omega^2 = F / (m loadDepth)), never stiffer than `maximumHertz`
  * (0.25 / substep: stiffer contacts jitter in piles). Its load is known from warm starting:
  * the force of its accumulated impulse over the last step. A stiffened contact keeps its
  * stiffness while it lasts (the contact table carries it from step to step, see `Stiffness`).
  *
  * A pair kept at the stiffness it had keeps its softness too: the contact table carries the
  * coefficients with the stiffness they were worked out for (`Stiffened`), and they are used
  * again while the substep and damping are the same, rather than worked out again, five
  * divisions and a root, for every loaded contact of a pile in every step.
  */
private[sims] final class ContactStiffness:
  private val normal = Softness()
  private val static = Softness()
  private var h, zeta, omega, maximumOmega, staticFactor, loadDepth = 0.0
  private var reuses = false

  /** Sets the step's stiffness: `hertz` (capped at `maximumHertz`), damping `zeta`, substep `h`;
    * `reuses` when the contacts' carried softness (see `Stiffened`) is of the same `zeta` and `h`.
    */
  def set(hertz: Double, maximumHertz: Double, zeta: Double, staticFactor: Double, loadDepth: Double, h: Double,
      reuses: Boolean): Unit =
    this.reuses = reuses
    this.h = h
    this.zeta = zeta
    this.staticFactor = staticFactor
    this.loadDepth = loadDepth
    omega = 2 * math.Pi * math.min(hertz, maximumHertz)
    maximumOmega = 2 * math.Pi * maximumHertz
    normal.set(omega / (2 * math.Pi), zeta, h)
    static.set(staticFactor * omega / (2 * math.Pi), zeta, h)

  /** Writes the softness of contact c (against a fixed body if `isStatic`) into its hot block.
    * Writes contact c's hot block and record alone (no scratch shared between contacts): contacts may be set
    * from several threads at once.
    */
  def set(contacts: Contacts, c: Int, isStatic: Boolean): Unit =
    val factor = if isStatic then staticFactor else 1.0
    val k = contacts.offset(c)
    val hot = contacts.hot
    val record = c * RecordStride
    var needed = 0.0
    if loadDepth > 0 then
      // The load as an acceleration of the effective mass: F / m = (impulse / h) / normalMass.
      var load = 0.0
      var p = 0
      while p < contacts.pointCount(c) do
        val q = contacts.hotPoint(c, p)
        if hot(q + NormalMass) > 0 then load = math.max(load, hot(q + NormalImpulse) / (h * hot(q + NormalMass)))
        p += 1
      // Never softer than the pair was: a stiffness that follows the load step by step pumps
      // energy into a loaded pile (a spring stiffer while compressed: parametric excitation).
      // Never beyond this step's limit either (the substeps or the pair's kind may have changed).
      val was = contacts.records(record + Stiffness)
      val squared = load / loadDepth
      val limit = factor * maximumOmega
      // Below the square of the stiffness it had by more than rounding, the root is below it too.
      needed =
        if squared < was * was * ContactStiffness.RootMargin && was <= limit then was
        else math.min(math.max(math.sqrt(squared), was), limit)
      contacts.records(record + Stiffness) = needed
    if needed > factor * omega then
      if !reuses || contacts.records(record + Stiffened) != needed then
        Softness.write(needed / (2 * math.Pi), zeta, h, hot, k + BiasRate)
        contacts.records(record + Stiffened) = needed
    else
      val soft = if isStatic then static else normal
      hot(k + BiasRate) = soft.biasRate
      hot(k + MassScale) = soft.massScale
      hot(k + ImpulseScale) = soft.impulseScale
      contacts.records(record + Stiffened) = 0

private[sims] object ContactStiffness:
  /** x < s^2 RootMargin, s^2 rounded, holds only where x < s^2 exactly, and then sqrt(x), rounded, is
    * at most s.
    */
  inline val RootMargin = 0.999999999999
