package sims.solver.soft

import sims.collision.PairTracker
import sims.solver.soft.ContactTable.*

/** Which of the soft step's contacts touch, for the world's contact events, after the substeps
  * and restitution: a contact touches when one of its points is at or below zero separation at
  * the end of the step, or applied a normal impulse during it. A speculative point (its shapes
  * up to a few centimetres apart) does not count until it pushes: then the shapes met within a
  * substep, though a bounce may part them again by the end of the step.
  *
  * A pair that begins is described by its normal, the middle of its touching points (where
  * they are at the end of the step), its approach speed (the fastest closing speed along the
  * normal at its points: at the start of the step, plus what gravity and forces added until
  * the point pushed, the impact's) and the normal impulse its points applied over the step.
  */
private[sims] object ContactTouching:
  /** Counts, for contacts `from until until` of `contacts` (this step's, after restitution), the
    * touching points of each contact c into `points(c)`. Writes only those contacts' slots:
    * ranges of contacts may be measured at once. What describes a pair is worked out by `report`
    * for the pairs that begin alone: most touching pairs go on touching.
    */
  def measure(contacts: Contacts, bodies: SoftBodies, points: Array[Int], from: Int, until: Int): Unit =
    val hot = contacts.hot
    val state = bodies.state
    var c = from
    while c < until do
      var touching = 0
      var p = 0
      while p < contacts.pointCount(c) do
        val q = contacts.hotPoint(c, p)
        if hot(q + TotalNormalImpulse) > 0 || ContactConstraints.separationNow(contacts, c, q, state) <= 0 then
          touching += 1
        p += 1
      points(c) = touching
      c += 1

  /** Reports the touching contacts of `contacts`, as `measure` counted them, to `tracker`, in
    * contact order (those of a shape whose contact events were off when the contact was made
    * left out), describing each pair that begins.
    */
  def report(contacts: Contacts, bodies: SoftBodies, tracker: PairTracker, points: Array[Int]): Unit =
    var c = 0
    while c < contacts.count do
      // The pair's key and whether its events are on, from the contact: no shape read unless it begins.
      if points(c) > 0 && contacts.reportsEvents(c) && tracker.touchKey(contacts.keys(c), contacts.shapeA(c),
          contacts.shapeB(c))
      then describe(contacts, bodies, tracker, c)
      c += 1

  /** Describes contact c's pair, which begins, to `tracker`: its normal, the middle of its
    * touching points (where they are at the end of the step), their fastest approach and the
    * normal impulse of all its points.
    */
  private def describe(contacts: Contacts, bodies: SoftBodies, tracker: PairTracker, c: Int): Unit =
    val hot = contacts.hot
    val state = bodies.state
    val k = contacts.offset(c)
    val nx = hot(k + NormalX); val ny = hot(k + NormalY)
    var touching = 0
    var sumX, sumY = 0.0
    var fastest = 0.0
    var impulse = 0.0
    var p = 0
    while p < contacts.pointCount(c) do
      val q = contacts.hotPoint(c, p)
      val pushed = hot(q + TotalNormalImpulse)
      if ContactConstraints.separationNow(contacts, c, q, state) <= 0 || pushed > 0 then
        touching += 1
        val point = ContactConstraints.pointNow(contacts, c, q, bodies)
        sumX += point.x
        sumY += point.y
        fastest = math.max(fastest, -contacts.records(contacts.recordPoint(c, p) + RelativeVelocity))
      impulse += pushed
      p += 1
    tracker.describe(nx, ny, sumX / touching, sumY / touching, fastest, impulse)
