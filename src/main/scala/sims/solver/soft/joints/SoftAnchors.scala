package sims.solver.soft.joints

import sims.solver.soft.SoftBodies
import sims.solver.soft.SoftBodies.*

/** A joint's two attachment points as the soft step moves them within a step, the part every
  * two-body joint's soft formulas share: the bodies' indices in the step's arrays, the arms from
  * each body's centre to its point at the start of the step, and, after any substep (`measure`),
  * those arms turned with their bodies and the offset between the centres. Nothing is computed
  * again from the bodies' placements during the step: the substeps move the bodies' arrays only.
  */
private[sims] final class SoftAnchors:
  /** Index of body 1 and of body 2 in the step's arrays. */
  var index1, index2 = 0
  private var startArm1X, startArm1Y, startArm2X, startArm2Y = 0.0
  private var startCentresX, startCentresY = 0.0 // centre2 - centre1 at the start of the step
  /** The arms from each body's centre to its point, turned with the bodies (set by `measure`). */
  var arm1X, arm1Y, arm2X, arm2Y = 0.0
  /** Body 2's centre minus body 1's (set by `measure`). */
  var centresX, centresY = 0.0

  /** Takes the bodies (by index) and their points' arms (arm = point - centre) at the start of
    * the step.
    */
  def start(bodies: SoftBodies, index1: Int, index2: Int, arm1X: Double, arm1Y: Double, arm2X: Double,
      arm2Y: Double): Unit =
    this.index1 = index1
    this.index2 = index2
    startArm1X = arm1X; startArm1Y = arm1Y
    startArm2X = arm2X; startArm2Y = arm2Y
    startCentresX = bodies.startX(index2) - bodies.startX(index1)
    startCentresY = bodies.startY(index2) - bodies.startY(index1)

  /** Sets the arms and the centres' offset from the bodies' motion since the step began (their
    * turn's cosine and sine, and their displacement, in `state`).
    */
  def measure(state: Array[Double]): Unit =
    val s1 = index1 * SoftBodies.Stride
    val s2 = index2 * SoftBodies.Stride
    arm1X = turnedArm1X(state, s1); arm1Y = turnedArm1Y(state, s1)
    arm2X = turnedArm2X(state, s2); arm2Y = turnedArm2Y(state, s2)
    centresX = currentCentresX(state, s1, s2)
    centresY = currentCentresY(state, s1, s2)

  // What `measure` sets, one value each, for a caller that keeps them in locals (body 1's state
  // at s1, body 2's at s2).
  /** Body 1's arm turned with it, x. */
  inline def turnedArm1X(state: Array[Double], s1: Int): Double =
    state(s1 + TurnCos) * startArm1X - state(s1 + TurnSin) * startArm1Y
  /** Body 1's arm turned with it, y. */
  inline def turnedArm1Y(state: Array[Double], s1: Int): Double =
    state(s1 + TurnSin) * startArm1X + state(s1 + TurnCos) * startArm1Y
  /** Body 2's arm turned with it, x. */
  inline def turnedArm2X(state: Array[Double], s2: Int): Double =
    state(s2 + TurnCos) * startArm2X - state(s2 + TurnSin) * startArm2Y
  /** Body 2's arm turned with it, y. */
  inline def turnedArm2Y(state: Array[Double], s2: Int): Double =
    state(s2 + TurnSin) * startArm2X + state(s2 + TurnCos) * startArm2Y
  /** Body 2's centre minus body 1's now, x. */
  inline def currentCentresX(state: Array[Double], s1: Int, s2: Int): Double =
    startCentresX + state(s2 + ShiftX) - state(s1 + ShiftX)
  /** Body 2's centre minus body 1's now, y. */
  inline def currentCentresY(state: Array[Double], s1: Int, s2: Int): Double =
    startCentresY + state(s2 + ShiftY) - state(s1 + ShiftY)
