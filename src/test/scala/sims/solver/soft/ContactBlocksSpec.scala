package sims.solver.soft

import org.scalatest.funsuite.AnyFunSuite
import sims.dynamics.{Circle, Rectangle, World}
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** The soft step's contacts in the passes' order (`ContactBlocks`): each active contact at one
  * place, each place with its contact's bodies, hot block and inverse masses, and the blocks of a
  * level without a moving body in common.
  */
class ContactBlocksSpec extends AnyFunSuite:
  /** Rows of balls side by side on a fixed floor, stepped once under `workers`. */
  private def stepped(columns: Int, rows: Int, workers: Int): World =
    val world = World()
    world.solver = SoftStep(workers = workers)
    val floor = Rectangle(2 * columns * 0.1 + 1, 0.2, 1)
    floor.pos = Vector2D(columns * 0.1, -0.1)
    val fixed = floor.asBody
    fixed.fixed = true
    world += fixed
    for row <- 0 until rows; column <- 0 until columns do
      val ball = Circle(0.1, 1)
      ball.pos = Vector2D(0.1 + 0.2 * column, 0.1 + 0.2 * row)
      world += ball.asBody
    world.step()
    world

  private def check(world: World, expectedLevels: Int): Unit =
    val workspace = world.workspace(classOf[SoftWorkspace], SoftWorkspace())
    val contacts = workspace.table.committed
    val bodies = workspace.bodies
    val blocks = workspace.passes.blocks
    assert(blocks.levels == expectedLevels)
    val blockCount = if blocks.levels == 1 then 1 else ContactBlocks.BlockCount
    assert(blocks.start(blockCount) == contacts.active)
    val seen = new Array[Int](contacts.active)
    for n <- 0 until contacts.active do
      val place = ContactBlocks.PlaceStride * n
      val c = blocks.places(place)
      seen(c) += 1
      val a = contacts.bodyA(c); val b = contacts.bodyB(c)
      assert(blocks.places(place + 1) == a * SoftBodies.Stride, s"place $n: body A")
      assert(blocks.places(place + 2) == b * SoftBodies.Stride, s"place $n: body B")
      assert(blocks.places(place + 3) == contacts.offset(c), s"place $n: hot block")
      val masses = blocks.placeMasses.slice(4 * n, 4 * n + 4).toSeq
      assert(masses == Seq(bodies.invMass(a), bodies.invI(a), bodies.invMass(b), bodies.invI(b)), s"place $n: masses")
    assert(seen.forall(_ == 1), "every active contact at exactly one place")
    // The blocks of one level share no moving body: the workers may solve them at once.
    for level <- 0 until blocks.levels do
      val owner = scala.collection.mutable.HashMap.empty[Int, Int]
      for index <- 0 until blocks.levelSize(level) do
        val block = blocks.levelStart(level) + index
        for n <- blocks.start(block) until blocks.start(block + 1) do
          val c = blocks.places(ContactBlocks.PlaceStride * n)
          for body <- Seq(contacts.bodyA(c), contacts.bodyB(c)) if bodies.invMass(body) != 0 do
            val first = owner.getOrElseUpdate(body, block)
            assert(first == block, s"body $body in blocks $first and $block")

  test("a small world is one block, its places the contacts in their two halves' turns") {
    val world = stepped(columns = 10, rows = 3, workers = 1)
    check(world, expectedLevels = 1)
    val blocks = world.workspace(classOf[SoftWorkspace], SoftWorkspace()).passes.blocks
    val active = world.workspace(classOf[SoftWorkspace], SoftWorkspace()).table.committed.active
    val half = (active + 1) / 2
    assert(blocks.places(0) == 0 && blocks.places(ContactBlocks.PlaceStride) == half)
  }

  test("a large world is cut into levels of blocks, on one worker and on two") {
    for workers <- Seq(1, 2) do check(stepped(columns = 80, rows = 40, workers = workers), ContactBlocks.Depth + 1)
  }
