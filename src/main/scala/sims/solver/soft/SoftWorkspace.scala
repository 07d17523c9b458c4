package sims.solver.soft

import sims.solver.soft.joints.SoftJoints

/** What the soft step keeps for one world: the bodies' arrays, the contact table and the joints'
  * constraints with their impulses (both carried from step to step), the collision stage and the
  * softness coefficients.
  */
private[sims] final class SoftWorkspace extends sims.dynamics.CarriedState:
  /** The bodies during a step. */
  val bodies: SoftBodies = SoftBodies()
  /** The contacts, this step's and the last step's. */
  val table: ContactTable = ContactTable()
  /** The collision stage. */
  val finder: ContactFinder = ContactFinder()
  /** What the joints read. */
  val context: SoftContext = SoftContext()
  /** The contacts' softness for the step. */
  val stiffness: ContactStiffness = ContactStiffness()
  /** The joints: their constraints, this step's force joints and joint trees. */
  val joints: SoftJoints = SoftJoints()
  /** The stages the worker threads share. */
  val passes: SoftPasses = SoftPasses(this)
  /** Sleeping: resting times and islands. */
  val islands: SleepIslands = SleepIslands()
  /** The world's `revision` at the end of the last step that collided its pairs, or -1: a step
    * in which every body sleeps may skip its collision stage only while it is unchanged.
    */
  var collidedRevision: Long = -1

  // The committed contacts when the step under way began: a failed step that already
  // committed its contacts swaps the generations back.
  private var committedAtStart: Contacts = null

  /** The committed contacts as copies, points and separations after the step's motion. */
  def contactViews(): IndexedSeq[sims.collision.Contact] =
    import ContactTable.*
    val contacts = table.committed
    val hot = contacts.hot
    val state = bodies.state
    IndexedSeq.tabulate(contacts.count) { c =>
      val k = contacts.offset(c)
      val nx = hot(k + NormalX)
      val ny = hot(k + NormalY)
      val count = contacts.pointCount(c)
      val points = IndexedSeq.tabulate(count)(p => ContactConstraints.pointNow(contacts, c, contacts.hotPoint(c, p), bodies))
      val separations =
        IndexedSeq.tabulate(count)(p => ContactConstraints.separationNow(contacts, c, contacts.hotPoint(c, p), state))
      def column(offset: Int) = IndexedSeq.tabulate(count)(p => hot(contacts.hotPoint(c, p) + offset))
      sims.collision.Contact(contacts.shapeA(c), contacts.shapeB(c), sims.geometry.Vector2D(nx, ny), points,
        separations, column(NormalImpulse), column(TangentImpulse), column(TotalNormalImpulse))
    }

  def copyState(): AnyRef = SoftWorkspace.Saved(table.copyCommitted(), joints.copyImpulses())

  def restoreState(saved: AnyRef): Unit = saved match
    case s: SoftWorkspace.Saved =>
      table.restoreCommitted(s.contacts)
      joints.restoreImpulses(s.impulses)
    case _ =>
      table.restoreCommitted(null)
      joints.restoreImpulses(null)

  def beginStep(): Unit =
    committedAtStart = table.committed
    joints.beginStep()

  def undoStep(): Unit =
    if table.committed ne committedAtStart then table.uncommit()
    joints.undoStep()

private[sims] object SoftWorkspace:
  /** A snapshot's copy of what the soft step carries: the committed contacts and the joints' impulses. */
  final class Saved(val contacts: Contacts, val impulses: SoftJoints.Saved)
