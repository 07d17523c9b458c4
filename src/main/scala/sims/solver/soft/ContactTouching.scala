package sims.solver.soft

import sims.collision.PairTracker
import sims.solver.soft.ContactTable.*
import sims.solver.soft.SoftBodies.*

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
  /** Doubles per contact in `measure`'s sums. */
  inline val SumStride = 4

  /** Measures contacts `from until until` of `contacts` (this step's, after restitution): per
    * contact c, its touching points in `points(c)` and, at `SumStride * c` in `sums`, the sums of
    * their x and y, their fastest approach and the contact's normal impulse. Writes only those
    * contacts' slots: ranges of contacts may be measured at once.
    */
  def measure(contacts: Contacts, bodies: SoftBodies, points: Array[Int], sums: Array[Double], from: Int,
      until: Int): Unit =
    val hot = contacts.hot
    val state = bodies.state
    var c = from
    while c < until do
      val a = contacts.bodyA(c)
      val b = contacts.bodyB(c)
      val sA = a * SoftBodies.Stride
      val sB = b * SoftBodies.Stride
      val k = contacts.offset(c)
      val nx = hot(k + NormalX); val ny = hot(k + NormalY)
      var touching = 0
      var sumX, sumY = 0.0
      var fastest = 0.0
      var impulse = 0.0
      var p = 0
      while p < contacts.pointCount(c) do
        val q = contacts.hotPoint(c, p)
        val rAx = hot(q + AnchorAX); val rAy = hot(q + AnchorAY)
        val rBx = hot(q + AnchorBX); val rBy = hot(q + AnchorBY)
        // The arms turned by each body's turn since the start of the step.
        val armAX = state(sA + TurnCos) * rAx - state(sA + TurnSin) * rAy
        val armAY = state(sA + TurnSin) * rAx + state(sA + TurnCos) * rAy
        val armBX = state(sB + TurnCos) * rBx - state(sB + TurnSin) * rBy
        val armBY = state(sB + TurnSin) * rBx + state(sB + TurnCos) * rBy
        val gapX = state(sB + ShiftX) - state(sA + ShiftX) + armBX - armAX
        val gapY = state(sB + ShiftY) - state(sA + ShiftY) + armBY - armAY
        val separation = gapX * nx + gapY * ny + hot(q + BaseSeparation)
        val pushed = hot(q + TotalNormalImpulse)
        if separation <= 0 || pushed > 0 then
          touching += 1
          sumX += bodies.startX(a) + state(sA + ShiftX) + armAX
          sumY += bodies.startY(a) + state(sA + ShiftY) + armAY
          fastest = math.max(fastest, -contacts.records(contacts.recordPoint(c, p) + RelativeVelocity))
        impulse += pushed
        p += 1
      points(c) = touching
      val t = SumStride * c
      sums(t) = sumX; sums(t + 1) = sumY; sums(t + 2) = fastest; sums(t + 3) = impulse
      c += 1

  /** Reports the touching contacts of `contacts`, as `measure` found them, to `tracker`, in
    * contact order (those of a shape whose contact events were off when the contact was made
    * left out).
    */
  def report(contacts: Contacts, tracker: PairTracker, points: Array[Int], sums: Array[Double]): Unit =
    val hot = contacts.hot
    var c = 0
    while c < contacts.count do
      val touching = points(c)
      // The pair's key and whether its events are on, from the contact: no shape read unless it begins.
      if touching > 0 && contacts.reportsEvents(c) && tracker.touchKey(contacts.keys(c), contacts.shapeA(c),
          contacts.shapeB(c))
      then
        val k = contacts.offset(c)
        val t = SumStride * c
        tracker.describe(hot(k + NormalX), hot(k + NormalY), sums(t) / touching, sums(t + 1) / touching, sums(t + 2),
          sums(t + 3))
      c += 1
