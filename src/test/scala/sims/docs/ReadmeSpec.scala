package sims.docs

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The README's usage example, verbatim, and what it claims. */
class ReadmeSpec extends AnyFunSuite with Matchers:
  test("the README example runs and the ball rests on the ground") {
    import sims.dynamics.{Circle, Rectangle, World}
    import sims.geometry.Vector2D

    val world = World()                         // gravity (0, -9.81), 60 steps per second
    val ground = Rectangle(10, 0.5, 1).asBody   // half extents 10 m x 0.5 m, density 1 kg/m^2
    ground.fixed = true
    val ball = Circle(0.2, 1).asBody            // radius 0.2 m
    ball.pos = Vector2D(0, 3)
    world += ground
    world += ball
    for _ <- 1 to 120 do world.step()           // two simulated seconds
    println(s"the ball rests at ${ball.pos}")   // on the ground: y about 0.7

    ball.pos.y shouldBe 0.7 +- 0.015
    ball.pos.x shouldBe 0.0
  }

  test("the README's code block is the one tested here") {
    val readme = scala.io.Source.fromFile("README.md").mkString
    val source = scala.io.Source.fromFile("src/test/scala/sims/docs/ReadmeSpec.scala").mkString
    val block = readme.split("```scala\n")(1).takeWhile(_ != '`').linesIterator.map(_.trim).filter(_.nonEmpty).toList
    val tested = source.linesIterator.map(_.trim).toList
    block.foreach(line => tested should contain(line))
  }
