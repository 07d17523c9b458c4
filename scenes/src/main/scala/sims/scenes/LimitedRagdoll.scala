package sims.scenes

import sims.dynamics.joints.{JointLimits, RevoluteJoint}
import sims.prefabs.Ragdoll

/** The Ragdoll prefab down the Ragdoll scene's stairs, its joints limited as a body's are:
  * elbows and knees bend one way only, shoulders and hips within a range. Runs under either
  * step (limits are one-sided corrections under the classic step).
  */
object LimitedRagdoll extends Scene:
  /** The limits of each kind of joint, radians (the lower part's turn from where it was made). */
  val Elbow: JointLimits = JointLimits(0, 2.4)
  val Knee: JointLimits = JointLimits(-2.4, 0)
  val Shoulder: JointLimits = JointLimits(-2.8, 0.6)
  val Hip: JointLimits = JointLimits(-1.8, 0.4)

  def name: String = "LimitedRagdoll"
  def description: String = "A ragdoll whose elbows and knees bend one way only, shoulders and hips within a range, down the stairs."
  def view: Region = RagdollScene.view
  override def region: Region = RagdollScene.region

  /** Each of the ragdoll's joints with the limits this scene gives it. */
  def limitsOf(ragdoll: Ragdoll): Seq[(RevoluteJoint, JointLimits)] =
    ragdoll.elbows.map(_ -> Elbow) ++ ragdoll.knees.map(_ -> Knee) ++ ragdoll.shoulders.map(_ -> Shoulder) ++
      ragdoll.hips.map(_ -> Hip)

  /** The scene's world and its ragdoll. */
  def stage(): (Staged, Ragdoll) =
    val world = RagdollScene.stairs()
    val ragdoll = Ragdoll(RagdollScene.DropPoint)
    for (joint, limits) <- limitsOf(ragdoll) do joint.limits = Some(limits)
    ragdoll.addTo(world)
    ragdoll.bodies.foreach(_.linearVelocity = RagdollScene.DropVelocity)
    (Staged(world), ragdoll)

  def build(): Staged = stage()._1
