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

  /** The ragdoll's start speed scaled by each of these: the fall is chaotic (a few percent of
    * speed changes which limb strikes which step first), so a single fall's worst moment says
    * little; eight falls' median says how well the limits hold.
    */
  private val speedScales = (0 until 8).map(k => 0.9 + 0.2 * k / 7)

  private def median(values: Seq[Double]): Double =
    val sorted = values.sorted
    0.5 * (sorted(sorted.length / 2 - 1) + sorted(sorted.length / 2))

  // How far a joint may go beyond its limits in the hardest impacts of a fall (the median of
  // eight falls): the classic step corrects them by its iterations, the soft step softly.
  for (label, solver, tolerance) <- Seq[(String, () => Solver, Double)](("ClassicStep", () => ClassicStep, 0.2),
      ("SoftStep", () => SoftStep(), 0.15)) do
    test(s"$label: down the stairs, every joint stays within its limits (the same ragdoll without them does not)") {
      val limited = speedScales.map { scale =>
        val (staged, ragdoll) = LimitedRagdoll.stage()
        staged.world.solver = solver()
        ragdoll.bodies.foreach(b => b.linearVelocity = b.linearVelocity * scale)
        val beyond = farthestBeyond(staged.world, LimitedRagdoll.limitsOf(ragdoll))
        ragdoll.bodies.map(_.pos.x).max should be > 3.0 // it went down the stairs
        beyond
      }
      // The plain Ragdoll scene: the same fall, no limits, measured against the same ones.
      val plain = RagdollScene.stairs()
      plain.solver = solver()
      val free = Ragdoll(RagdollScene.DropPoint)
      free.addTo(plain)
      free.bodies.foreach(_.linearVelocity = RagdollScene.DropVelocity)
      val unlimited = farthestBeyond(plain, LimitedRagdoll.limitsOf(free))
      info(f"farthest beyond a limit: median ${median(limited)}%.3f rad of eight falls with limits " +
        f"(${limited.map(v => f"$v%.3f").mkString(", ")}), $unlimited%.3f rad without")
      median(limited) should be < tolerance
      unlimited should be > 0.3
    }
