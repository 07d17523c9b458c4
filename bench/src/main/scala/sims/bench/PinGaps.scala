package sims.bench

import sims.dynamics.joints.RevoluteJoint
import sims.solver.{Solver, SoftStep}

/** How far a jointed scene's pins open over time (default `joint_grid` under `SoftStep(workers =
  * 1)`, `--classic` for the classic step): every `--every N` steps (default 100) the largest and
  * the mean distance between the two anchor points of its revolute joints, and at the end the
  * largest over the whole run of `--steps N` steps (default 1200). Sleeping is off, as in the
  * bench. The bench's sanity check reads the gaps once, after its run; this shows how they swing.
  */
object PinGaps:
  def main(args: Array[String]): Unit =
    var steps = 1200
    var every = 100
    var solver: Solver = SoftStep(workers = 1)
    var name = "joint_grid"
    val it = args.iterator
    while it.hasNext do
      it.next() match
        case "--steps" => steps = it.next().toInt
        case "--every" => every = it.next().toInt
        case "--classic" => solver = sims.solver.ClassicStep
        case scene => name = scene
    val world = SimsBuilder.world(Settings.scene(name), solver)
    val pins = world.joints.collect { case j: RevoluteJoint => j }.toIndexedSeq
    require(pins.nonEmpty, s"$name has no revolute joints")
    println(s"$name, $solver: ${pins.size} pins")
    var largestEver = 0.0
    var largestAt = 0
    for step <- 1 to steps do
      world.step()
      var largest = 0.0
      var sum = 0.0
      for pin <- pins do
        val gap = pin.separation
        sum += gap
        largest = math.max(largest, gap)
      if largest > largestEver then
        largestEver = largest
        largestAt = step
      if step % every == 0 then
        println(f"step $step%5d: largest pin gap ${largest * 1000}%.1f mm, mean ${sum / pins.size * 1000}%.2f mm")
    println(f"largest over the run: ${largestEver * 1000}%.1f mm at step $largestAt")
