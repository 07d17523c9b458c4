package sims.prefabs

import org.scalatest.funsuite.AnyFunSuite
import sims.dynamics.World
import sims.dynamics.joints.DistanceJoint
import sims.geometry.Vector2D

/** The Net prefab: its layout, its joints, and a net hanging from one corner. */
class NetSpec extends AnyFunSuite:
  test("nodes are laid out row by row from the lower-left node"):
    val net = Net(4, 3, Vector2D(1, 2), spacing = 0.5)
    assert(net.bodies.size == 12)
    assert(net.node(0, 0).pos == Vector2D(1, 2))
    assert(net.node(3, 0).pos == Vector2D(2.5, 2))
    assert(net.node(1, 2).pos == Vector2D(1.5, 3))
    assert(net.bodies(2 * 4 + 1) eq net.node(1, 2))

  test("each node is joined to its right and upper neighbours"):
    val net = Net(4, 3, Vector2D.Null)
    // (width - 1) * height horizontal and width * (height - 1) vertical links.
    assert(net.joints.size == 3 * 3 + 4 * 2)
    val pairs = net.joints.map { case j: DistanceJoint => (j.node1, j.node2); case j => fail(s"unexpected $j") }
    assert(pairs.contains((net.node(0, 0), net.node(1, 0))))
    assert(pairs.contains((net.node(0, 0), net.node(0, 1))))
    assert(!pairs.contains((net.node(0, 0), net.node(1, 1))), "no diagonals")
    for j <- net.joints do
      assert(math.abs(j.asInstanceOf[DistanceJoint].distance - sims.Defaults.NetSpacing) < 1e-12)

  test("a single node has no joints; bad sizes are refused"):
    assert(Net(1, 1, Vector2D.Null).joints.isEmpty)
    intercept[IllegalArgumentException](Net(0, 3, Vector2D.Null))
    intercept[IllegalArgumentException](Net(3, 3, Vector2D.Null, spacing = 0.05))

  test("a net hanging from one corner swings down and its links hold"):
    val world = World()
    val net = Net(10, 10, Vector2D.Null)
    net.node(0, 9).fixed = true
    net.addTo(world)
    assert(world.bodies.size == 100 && world.joints.size == 180)
    for _ <- 1 to 180 do world.step()
    val corner = net.node(0, 9).pos
    assert(corner == Vector2D(0, 9 * sims.Defaults.NetSpacing), "the fixed corner stays")
    assert(net.node(9, 0).pos.y < corner.y - 1, "the free corner has fallen below the fixed one")
    val worstStretch = net.joints.map {
      case j: DistanceJoint => math.abs((j.connection2 - j.connection1).length - j.distance) / j.distance; case _ => 0.0
    }.max
    // With 10 solver iterations the links near the fixed corner, which carry the other 99
    // nodes, stretch a lot while the net swings (47 % measured after 3 s); the bound pins that
    // they stretch, but do not tear apart.
    assert(worstStretch < 0.6, s"links stretched by up to ${worstStretch * 100} %")
    val meanStretch = net.joints.map {
      case j: DistanceJoint => math.abs((j.connection2 - j.connection1).length - j.distance) / j.distance; case _ => 0.0
    }.sum / net.joints.size
    assert(meanStretch < 0.1, s"links stretched by ${meanStretch * 100} % on average")
