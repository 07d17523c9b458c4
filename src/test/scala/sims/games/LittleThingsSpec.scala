package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Capsule, Circle, HullPolygon, Rectangle, RegularPolygon, World}
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** What a new user meets first: default densities, Vector2D.Zero and `2.0 * v`, readable prints. */
class LittleThingsSpec extends AnyFunSuite with Matchers:
  test("shapes' density defaults to 1") {
    Circle(0.5).density shouldBe 1.0
    Circle(0.5).mass shouldBe math.Pi * 0.25
    Rectangle(1, 2).mass shouldBe 8.0
    RegularPolygon(5, 1).density shouldBe 1.0
    Capsule(1, 0.5).density shouldBe 1.0
    HullPolygon(Seq(Vector2D(0, 0), Vector2D(1, 0), Vector2D(0, 1))).mass shouldBe 0.5 +- 1e-12
  }

  test("Vector2D.Zero is Null, and a number times a vector is the vector times the number") {
    Vector2D.Zero shouldBe Vector2D.Null
    Vector2D.Zero shouldBe Vector2D(0, 0)
    val v = Vector2D(1.5, -2)
    2.0 * v shouldBe Vector2D(3, -4)
    2.0 * v shouldBe v * 2
    0.1 * v shouldBe v * 0.1
  }

  test("SoftStep and World print their parameters by name and their counts") {
    val text = SoftStep().toString
    // Numbers as the platform prints them (Scala.js prints 30.0 as 30).
    text should startWith(s"SoftStep(substeps = 4, contactHertz = ${30.0}")
    text should include("directJoints = true")
    val world = World()
    world += Circle(0.5).asBody
    world.toString shouldBe s"World(bodies = 1, joints = 0, shapes = 1, time = ${0.0} s, solver = ClassicStep)"
    world.solver = SoftStep(substeps = 8)
    world.step()
    world.toString should (include("bodies = 1") and include("solver = SoftStep(substeps = 8,"))
  }
