package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.World
import sims.dynamics.joints.{JointLimits, RevoluteJoint}
import sims.prefabs.Ragdoll
import sims.solver.{ClassicStep, SoftStep, Solver}

/** The LimitedRagdoll scene does what its description says, under either step. */
class LimitedRagdollSpec extends AnyFunSuite with Matchers:
  /** The farthest any joint went beyond its limits over 5 s (rad, 0 if none did). */
  private def farthestBeyond(world: World, joints: Seq[(RevoluteJoint, JointLimits)]): Double =
    var farthest = 0.0
    for _ <- 1 to 300 do
      world.step()
      for (joint, limits) <- joints do
        farthest = math.max(farthest, math.max(limits.lower - joint.angle, joint.angle - limits.upper))
    farthest

  // How far a joint may go beyond its limits in the hardest impacts of the fall: the classic
  // step corrects them by its iterations (0.14 rad measured), the soft step softly (0.074 rad).
  for (label, solver, tolerance) <- Seq[(String, () => Solver, Double)](("ClassicStep", () => ClassicStep, 0.2),
      ("SoftStep", () => SoftStep(), 0.1)) do
    test(s"$label: down the stairs, every joint stays within its limits (the same ragdoll without them does not)") {
      val (staged, ragdoll) = LimitedRagdoll.stage()
      staged.world.solver = solver()
      val limited = farthestBeyond(staged.world, LimitedRagdoll.limitsOf(ragdoll))
      // The plain Ragdoll scene: the same fall, no limits, measured against the same ones.
      val plain = RagdollScene.stairs()
      plain.solver = solver()
      val free = Ragdoll(RagdollScene.DropPoint)
      free.addTo(plain)
      free.bodies.foreach(_.linearVelocity = RagdollScene.DropVelocity)
      val unlimited = farthestBeyond(plain, LimitedRagdoll.limitsOf(free))
      info(f"farthest beyond a limit: $limited%.3f rad with limits, $unlimited%.3f rad without")
      limited should be < tolerance
      unlimited should be > 0.3
      ragdoll.bodies.map(_.pos.x).max should be > 3.0 // it went down the stairs
    }
