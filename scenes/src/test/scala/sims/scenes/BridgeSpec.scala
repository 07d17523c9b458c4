package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.JointBreak

/** The Bridge scene does what its description says (under the soft step, its only one). */
class BridgeSpec extends AnyFunSuite with Matchers:
  import Bridge.*

  test("without the load the bridge holds its own weight for 5 s: no joint breaks, it sags less than 10 cm more") {
    val (staged, bridge) = stage(withLoad = false)
    val world = staged.world
    val built = bridge.planks.map(_.pos.y).min
    var strongest = 0.0
    var widest = 0.0
    for _ <- 1 to 300 do
      world.step()
      world.jointBreaks shouldBe empty
      strongest = math.max(strongest, bridge.joints.map(_.reactionForce.length).max)
      widest = math.max(widest, bridge.joints.map(_.separation).max)
    val sag = built - bridge.planks.map(_.pos.y).min
    info(f"sagged $sag%.3f m more than built; the strongest pull $strongest%.1f N (breaks at $BreakForce%.0f N); " +
      f"pins at most $widest%.4f m apart")
    world.joints.size shouldBe Planks + 1
    sag should be < 0.1 // 0.056 m measured
    strongest should be < BreakForce / 4 // 51 N measured
    widest should be < 0.01
  }

  test("the bridge holds for the first second; the load dropped then breaks joints (reported, removed) and falls through") {
    val (staged, bridge) = stage()
    val world = staged.world.asInstanceOf[BridgeWorld]
    var breaks = IndexedSeq.empty[JointBreak]
    var step = 0
    while breaks.isEmpty && step < 180 do
      world.step()
      step += 1
      breaks = world.jointBreaks
      if step < DropStep then world.load shouldBe None
    val broken = breaks.map(b => bridge.joints.indexOf(b.joint))
    info(
      f"joints ${broken.mkString(", ")} (0 at the left pier) broke at step $step, pulling with ${breaks.map(_.force.length).min}%.0f N or more")
    step should be > DropStep // the bridge held its own weight until the load came
    breaks should not be empty
    for b <- breaks do
      b.force.length should be > BreakForce
      bridge.joints should contain(b.joint)
      world.joints should not contain b.joint
    world.joints.size shouldBe (Planks + 1 - breaks.size)
    for _ <- 1 to 120 do world.step()
    // Two seconds later the load lies below the deck's lowest point as built, down by the river bed.
    val load = world.load.get
    load.pos.y should be < Pins.map(_.y).min - 1
    math.abs(load.pos.x) should be < HalfGap // it fell through, between the piers
  }
