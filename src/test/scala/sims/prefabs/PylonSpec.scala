package sims.prefabs

import org.scalatest.funsuite.AnyFunSuite
import sims.dynamics.{Rectangle, World}
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

/** The Pylon prefab: its layout, its bracing, and a pylon standing on the ground. */
class PylonSpec extends AnyFunSuite:
  test("two columns of levels + 1 nodes"):
    val pylon = Pylon(Vector2D(1, 0), levels = 3, width = 2, levelHeight = 1.5)
    assert(pylon.bodies.size == 8)
    assert(pylon.node(0, 0).pos == Vector2D(1, 0))
    assert(pylon.node(0, 1).pos == Vector2D(3, 0))
    assert(pylon.node(3, 1).pos == Vector2D(3, 4.5))

  test("each panel has two columns, a crossbar below and one diagonal; the top has its crossbar"):
    val pylon = Pylon(Vector2D.Null, levels = 3)
    assert(pylon.joints.size == 4 * 3 + 1)
    val pairs = pylon.joints.map { case j: DistanceJoint => Set(j.node1, j.node2); case j => fail(s"unexpected $j") }
    assert(pairs.distinct.size == pairs.size, "no link twice")
    assert(pairs.contains(Set(pylon.node(0, 0), pylon.node(1, 1))), "diagonal of panel 0")
    assert(pairs.contains(Set(pylon.node(1, 1), pylon.node(2, 0))), "diagonal of panel 1, the other way")
    assert(pairs.contains(Set(pylon.node(3, 0), pylon.node(3, 1))), "top crossbar")

  test("bad sizes are refused"):
    intercept[IllegalArgumentException](Pylon(Vector2D.Null, levels = 0))
    intercept[IllegalArgumentException](Pylon(Vector2D.Null, width = 0.1))

  test("a pylon standing on the ground stays up"):
    val world = World()
    val ground = Rectangle(10, 0.5, 1)
    ground.pos = Vector2D(0, -0.5)
    val groundBody = ground.asBody
    groundBody.fixed = true
    world += groundBody
    val pylon = Pylon(Vector2D(-0.5, sims.Defaults.PylonNodeRadius), levels = 6)
    pylon.addTo(world)
    for _ <- 1 to 300 do world.step()
    val top = pylon.node(6, 0).pos
    assert(math.abs(top.y - (6 + sims.Defaults.PylonNodeRadius)) < 0.2, s"top node at $top")
    assert(math.abs(top.x + 0.5) < 0.2, s"top node at $top")
