package sims.docs

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The README's usage example, verbatim, and what it claims. */
class ReadmeSpec extends AnyFunSuite with Matchers:
  test("the README example runs and the stack of five boxes stands at rest") {
    import sims.dynamics.{Rectangle, World}
    import sims.geometry.Vector2D
    import sims.solver.SoftStep

    val world = World()                         // gravity (0, -9.81), 60 steps per second
    world.solver = SoftStep()                   // substeps, soft contacts, warm starting
    val ground = Rectangle(10, 0.5).asBody      // half extents 10 m x 0.5 m, density 1 kg/m^2
    ground.fixed = true                         // its top face at y = 0.5
    world += ground
    val boxes = for i <- 0 until 5 yield
      val box = Rectangle(0.5, 0.25).asBody     // a box of 1 m x 0.5 m
      box.pos = Vector2D(0.02 * i, 0.76 + 0.51 * i)
      world += box
      box
    for _ <- 1 to 120 do world.step()           // two simulated seconds
    println(boxes.map(b => f"${b.pos.y}%.2f").mkString(" ")) // the stack stands: 0.75 1.25 1.75 2.25 2.75

    for (b, i) <- boxes.zipWithIndex do
      b.pos.y shouldBe (0.75 + 0.5 * i) +- 0.015
      b.pos.x shouldBe (0.02 * i) +- 0.01
      b.linearVelocity.length should be < 0.01
    boxes.map(b => f"${b.pos.y}%.2f").mkString(" ") shouldBe "0.75 1.25 1.75 2.25 2.75"
  }

  test("the README says when to choose the classic step") {
    val readme = scala.io.Source.fromFile("README.md").mkString
    readme should include("choose SiMS's own\nstep, `ClassicStep`")
  }

  test("the README's WebAssembly linker setting is the one the bench page's WebAssembly build uses") {
    val readme = scala.io.Source.fromFile("README.md").mkString
    val build = scala.io.Source.fromFile("build.sbt").mkString
    val setting = "scalaJSLinkerConfig ~= (_.withExperimentalUseWebAssembly(true).withModuleKind(ModuleKind.ESModule))"
    readme should include(setting)
    build should include(setting)
  }

  test("the README's code block is the one tested here") {
    val readme = scala.io.Source.fromFile("README.md").mkString
    val source = scala.io.Source.fromFile("src/test/scala/sims/docs/ReadmeSpec.scala").mkString
    val block = readme.split("```scala\n")(1).takeWhile(_ != '`').linesIterator.map(_.trim).filter(_.nonEmpty).toList
    val tested = source.linesIterator.map(_.trim).toList
    block.foreach(line => tested should contain(line))
  }
