package sims.examples

import sims.dynamics.{Body, Circle, World}
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

/** Main job: a pendulum run headless, printing the bob's position every half second. */
@main def runPendulum(): Unit =
  val world = World()
  val pivot = Body(Circle(0.05, 1)); pivot.fixed = true
  val bob = Body(Circle(0.1, 1)); bob.pos = Vector2D(1, 0)
  world += pivot
  world += bob
  world += DistanceJoint(pivot, pivot.pos, bob, bob.pos)
  world.enableCollisionDetection = false
  val stepsPerPrint = math.round(0.5 / world.timeStep).toInt
  for i <- 0 to 10 do
    if i > 0 then for _ <- 1 to stepsPerPrint do world.step()
    println(f"t = ${world.time}%5.2f s  bob at (${bob.pos.x}%7.4f, ${bob.pos.y}%7.4f)")
