package sims.collision

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Circle, World}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** `World.contacts` and the contact events agree under both steps: once collision detection is
  * switched off, the pairs' events end and the world lists no contacts (the classic step used to
  * list the last detection's collisions, re-measured at the new positions: 71 "touching" in a
  * pile whose events had all ended).
  */
class ContactsAgreeWithEventsSpec extends AnyFunSuite with Matchers:
  private def pile(solver: Solver): World =
    val (world, _) = ContactEventsSpec.withGround(solver)
    for i <- 0 until 40 do
      val ball = Circle(0.2, 1).asBody
      ball.pos = Vector2D(-2 + 0.45 * (i % 10), 0.2 + 0.41 * (i / 10))
      world += ball
    world

  private def pairs(world: World): Set[(Int, Int)] =
    world.contacts.filter(_.touching).map(c => (c.shape1.worldIndex, c.shape2.worldIndex)).map((a, b) =>
      (math.min(a, b), math.max(a, b))).toSet

  for solver <- Seq[Solver](ClassicStep, SoftStep()) do
    test(s"${sims.dynamics.StepGuard.solverName(solver)}: no contacts once detection is off, as the events say") {
      val world = pile(solver)
      for _ <- 1 to 60 do world.step()
      val touching = world.contactEvents.touching.map((a, b) => (a.worldIndex, b.worldIndex)).toSet
      touching.size should be >= 40
      pairs(world) should not be empty
      pairs(world).subsetOf(touching) shouldBe true
      world.enableCollisionDetection = false
      world.step()
      world.contactEvents.ends.size shouldBe touching.size
      world.contactEvents.touching shouldBe empty
      world.contacts shouldBe empty
      world.enableCollisionDetection = true
      world.step()
      pairs(world) should not be empty
    }
