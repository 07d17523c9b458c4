package sims.solver.soft.joints

import sims.dynamics.joints.{DistanceJoint, ForceJoint, Joint, MotorJoint, MouseJoint, PrismaticJoint, RevoluteJoint, WeldJoint, WheelJoint}
import sims.solver.soft.SoftContext

/** A joint as the soft step solves it (see docs/two-solvers.md): the joint says what is
  * constrained (its anchors, its settings); its constraint here does the soft step's work on
  * it, each stage a method, as Box2D keeps one file per joint with its prepare and solve
  * functions. The constraint owns everything the soft step keeps for its joint: the impulses it
  * accumulates (warm started from step to step) and its geometry during a step, so the classic
  * step's fields and these are never the same.
  *
  * @param joint the joint this constrains
  * @param rows the number of rows of the constraint: its accumulated impulses, one per row
  */
private[sims] abstract class JointConstraint(val joint: Joint, rows: Int):
  require(rows <= JointConstraint.MaxRows, s"a joint constraint has at most ${JointConstraint.MaxRows} rows, not $rows")

  /** The impulses accumulated so far, one per row: carried to the next step (warm starting). */
  val impulse: Array[Double] = new Array[Double](rows)

  /** Whether this step solves the constraint's rows in a joint tree (set before `prepare`): then
    * `solve` is not called, and `prepare` may leave out what only `solve` reads.
    */
  var inTree: Boolean = false

  /** Takes what stays fixed during the step, with the bodies at their placements at its start. */
  def prepare(context: SoftContext): Unit

  /** The number of rows this constraint gives the direct solver of joint trees (`rowsAt`), or 0
    * when it is solved iteratively by `solve` only.
    */
  def directRows: Int = 0

  /** The constraint's rows at the current substep, for the direct solver. */
  def rowsAt(context: SoftContext, rows: JointRows): Unit = ()

  /** Whether `solveAxial` solves anything this step (set by `prepare`). */
  def solvesAxial: Boolean = false

  /** The part of the constraint the direct solver of joint trees does not solve (a joint's
    * limits, motor, spring), one pass of it; `solve` runs it too. Nothing by default.
    */
  def solveAxial(context: SoftContext, useBias: Boolean): Unit = ()

  /** Sets the joint's reaction force and torque from the impulses accumulated in the step
    * (each substep applies them whole: impulse per substep times 1 / substep, `inverseH`).
    * Nothing by default (a user's joint's load is not known).
    */
  def report(inverseH: Double): Unit = ()

  /** Applies the impulses accumulated so far. */
  def warmStart(context: SoftContext): Unit

  /** One pass of the constraint, with the soft bias (`useBias`, the solve pass) or without (the
    * relax pass).
    */
  def solve(context: SoftContext, useBias: Boolean): Unit

/** The soft step's table of joint kinds. */
private[sims] object JointConstraint:
  /** The most rows a constraint has (a revolute or prismatic joint's: point, limit, motor). */
  inline val MaxRows = 6

  /** The soft constraint of `joint`, or null for a force joint (a spring: its forces are applied
    * in every substep instead). A joint of a kind the table does not know (a user's own) is
    * solved by its classic velocity correction ([[ClassicConstraint]]).
    */
  def of(joint: Joint): JointConstraint = joint match
    case j: DistanceJoint => DistanceConstraint(j)
    case j: RevoluteJoint => RevoluteConstraint(j)
    case j: PrismaticJoint => PrismaticConstraint(j)
    case j: MouseJoint => MouseConstraint(j)
    case j: WeldJoint => WeldConstraint(j)
    case j: WheelJoint => WheelConstraint(j)
    case j: MotorJoint => MotorConstraint(j)
    case _: ForceJoint => null
    case j => ClassicConstraint(j)

  /** The number of impulses `joint`'s constraint carries (0 for a force joint). */
  def rowsOf(joint: Joint): Int =
    val c = of(joint)
    if c == null then 0 else c.impulse.length
