package sims.robustness

import org.scalacheck.{Gen, Shrink}
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, Shape, World}
import sims.dynamics.joints.{DistanceJoint, SpringJoint}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Random scenes, under both solvers: nothing a valid input does may produce an undocumented
  * error or a NaN.
  */
class FuzzSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  /** The recipe of one body: kind, size (0.05 to 5 m), density, position, velocities, material. */
  private final case class BodySpec(kind: Int, size: Double, density: Double, x: Double, y: Double,
      vx: Double, vy: Double, w: Double, restitution: Double, friction: Double, fixed: Boolean)

  private val bodySpec: Gen[BodySpec] =
    for
      kind <- Gen.choose(0, 2)
      size <- Gen.choose(math.log(0.05), math.log(5.0)).map(math.exp)
      density <- Gen.choose(math.log(0.1), math.log(10.0)).map(math.exp)
      x <- Gen.choose(-10.0, 10.0)
      y <- Gen.choose(-10.0, 10.0)
      vx <- Gen.choose(-10.0, 10.0)
      vy <- Gen.choose(-10.0, 10.0)
      w <- Gen.choose(-5.0, 5.0)
      restitution <- Gen.choose(0.0, 1.0)
      friction <- Gen.choose(0.0, 1.0)
      fixed <- Gen.frequency(9 -> false, 1 -> true)
    yield BodySpec(kind, size, density, x, y, vx, vy, w, restitution, friction, fixed)

  /** Scene recipe: bodies, and joints as (body index, body index, spring?) */
  private val sceneSpec: Gen[(List[BodySpec], List[(Int, Int, Boolean)])] =
    for
      n <- Gen.choose(2, 14)
      bodies <- Gen.listOfN(n, bodySpec)
      joints <- Gen.listOf(for a <- Gen.choose(0, n - 1); b <- Gen.choose(0, n - 1); s <- Gen.oneOf(true, false) yield (a, b, s))
    yield (bodies, joints.filter((a, b, _) => a != b).take(6))

  // Shrinking would break the recipes' invariants (joint indices, distinct bodies).
  private given Shrink[(List[BodySpec], List[(Int, Int, Boolean)])] = Shrink.shrinkAny

  private def build(spec: (List[BodySpec], List[(Int, Int, Boolean)]), gravity: Boolean, springs: Boolean,
      solver: Solver): World =
    val world = World()
    world.solver = solver
    if !gravity then world.gravity = Vector2D.Null
    val bodies = spec._1.map { s =>
      val shape: Shape = s.kind match
        case 0 => Circle(s.size, s.density)
        case 1 => Rectangle(s.size, s.size * 0.6, s.density)
        case _ => RegularPolygon(3 + (s.size * 10).toInt % 6, s.size, s.density)
      shape.pos = Vector2D(s.x, s.y)
      shape.restitution = s.restitution
      shape.friction = s.friction
      val b = shape.asBody
      b.linearVelocity = Vector2D(s.vx, s.vy)
      b.angularVelocity = s.w
      b.fixed = s.fixed
      world += b
      b
    }
    for (a, b, spring) <- spec._2 if a != b && a < bodies.size && b < bodies.size do
      val (p, q) = (bodies(a), bodies(b))
      // Stiffness scaled to the lighter body keeps the explicit spring stable (period ~1.4 s).
      if spring && springs then world += SpringJoint(p, q, 20 * math.min(p.mass, q.mass).min(1e6))
      else if !spring && (p.pos - q.pos).length > 1e-6 then world += DistanceJoint(p, p.pos, q, q.pos)
    world

  private def finite(world: World): Boolean = world.bodies.forall(b =>
    b.pos.isFinite && b.linearVelocity.isFinite && !b.rotation.isNaN && !b.angularVelocity.isNaN)

  private def kinetic(world: World): Double = world.bodies.filterNot(_.fixed).map(b =>
    0.5 * b.mass * (b.linearVelocity dot b.linearVelocity) + 0.5 * b.I * b.angularVelocity * b.angularVelocity).sum

  for solver <- Seq(ClassicStep, SoftStep()) do
    val name = World.solverName(solver)

    test(s"$name: random scenes with gravity, joints and springs run 2,000 steps without errors or NaN", sims.SlowTest) {
      forAll(sceneSpec, minSuccessful(8)) { spec =>
        val world = build(spec, gravity = true, springs = true, solver)
        for _ <- 1 to 2000 do world.step()
        finite(world) shouldBe true
      }
    }

    test(s"$name: in zero gravity, with restitution <= 1 and no springs, kinetic energy never rises above 105%", sims.SlowTest) {
      forAll(sceneSpec, minSuccessful(8)) { spec =>
        val world = build(spec, gravity = false, springs = false, solver)
        val start = kinetic(world)
        for _ <- 1 to 2000 do
          world.step()
          kinetic(world) should be <= 1.05 * start + 1e-9
        finite(world) shouldBe true
      }
    }

    test(s"$name: a spring too stiff for the time step (k = 1e12) is rejected where it is added, naming the limit (issue 16)") {
      val world = World()
      world.solver = solver
      val (a, b) = pair(world)
      val error = intercept[IllegalArgumentException](world += SpringJoint(a, b, 1e12))
      error.getMessage should include("too stiff for the time step")
      error.getMessage should include("diverge from 4.0 on")
      world.joints shouldBe empty
    }

    test(s"$name: a spring made too stiff by a longer time step fails the next step before anything changes") {
      val world = World()
      world.solver = solver
      val (a, b) = pair(world)
      world += SpringJoint(a, b, 0.1)
      for _ <- 1 to 10 do world.step()
      val before = (world.time, a.pos, b.pos, b.linearVelocity)
      world.timeStep = 1 // (k h^2) / m = 0.1 / (0.8 g / 2) = 255
      intercept[IllegalStateException](world.step()).getMessage should include("too stiff")
      (world.time, a.pos, b.pos, b.linearVelocity) shouldBe before
    }

    test(s"$name: a spring just inside the stability limit oscillates with bounded amplitude for 10,000 steps") {
      val world = World()
      world.solver = solver
      world.gravity = Vector2D.Null
      val (a, b) = pair(world)
      val h = solver.forceInterval(world)
      val k = 3.6 / (h * h * (a.invMassForTests + b.invMassForTests)) // stability number 3.6 of 4
      world += SpringJoint(a, b, k)
      b.linearVelocity = Vector2D(1, 0)
      var widest = 0.0
      for _ <- 1 to 10000 do
        world.step()
        widest = math.max(widest, math.abs(b.pos.x - a.pos.x))
      widest should be < 2.0 // starts 0.5 m apart; a diverging spring leaves every bound behind
    }

  /** Two light balls 0.5 m apart, in `world`. */
  private def pair(world: World): (Body, Body) =
    val a = Circle(0.05, 0.1).asBody // 0.8 g
    val b = Circle(0.05, 0.1).asBody
    b.pos = Vector2D(0.5, 0)
    world += a
    world += b
    (a, b)

  extension (body: Body) private def invMassForTests: Double = 1 / body.mass
