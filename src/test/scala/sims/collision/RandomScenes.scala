package sims.collision

import org.scalacheck.Gen
import sims.dynamics.{Body, Capsule, Circle, Edge, HullPolygon, Rectangle, RegularPolygon, Shape, World}
import sims.geometry.Vector2D

/** Random scenes for the tests that compare the grid with brute force: shapes of every size
  * (small, middling, larger than grid cells) scattered over 40 m, some sharing a body, on a
  * huge ground.
  */
object RandomScenes:
  /** A shape of one of the first `kinds` kinds: circle, rectangle, pentagon, hull, capsule, edge. */
  def shape(kinds: Int): Gen[Shape] =
    for
      size <- Gen.oneOf(Gen.choose(0.01, 0.3), Gen.choose(0.3, 3.0), Gen.choose(3.0, 30.0))
      kind <- Gen.choose(0, kinds - 1)
      x <- Gen.choose(-20.0, 20.0)
      y <- Gen.choose(-20.0, 20.0)
      rotation <- Gen.choose(0.0, 3.0)
    yield
      val s = kind match
        case 0 => Circle(size, 1)
        case 1 => Rectangle(size, size / 2, 1)
        case 2 => RegularPolygon(5, size, 1)
        case 3 => HullPolygon(Seq(Vector2D(0, 0), Vector2D(size, 0), Vector2D(0.2 * size, size)), 1)
        case 4 => Capsule(size, size / 4, 1)
        case _ => Edge(Vector2D(-size, 0), Vector2D(size, 0))
      s.pos = Vector2D(x, y)
      s.rotation = rotation
      s

  /** A world of grid side `gridSide` with a huge ground and the shapes, two by two: every third
    * pair one body, the others a body each; with `someNotCollidable`, one shape of every fourth
    * pair not collidable.
    */
  def scene(shapes: Seq[Shape], gridSide: Double, someNotCollidable: Boolean = false): World =
    val world = World()
    world.detector.asInstanceOf[GridDetector].gridSide = gridSide
    val ground = Rectangle(200, 5, 1)
    ground.pos = Vector2D(0, -10)
    world += ground.asBody
    shapes.grouped(2).zipWithIndex.foreach { (group, i) =>
      if i % 3 == 0 then world += Body(group*) else group.foreach(s => world += s.asBody)
      if someNotCollidable && i % 4 == 1 then group.head.collidable = false
    }
    world
