package sims.solver.soft

/** What the joints' soft-step methods read during one step: the bodies' arrays, the substep,
  * and the softness of rigid joints.
  */
private[sims] final class SoftContext:
  /** The bodies of the step. */
  var bodies: SoftBodies = null
  /** Length of a substep, s. */
  var h: Double = 0
  /** 1 / h. */
  var inverseH: Double = 0
  /** The softness of rigid joints for this substep (from `jointHertz`, `jointDampingRatio`). */
  val jointSoftness: Softness = Softness()
