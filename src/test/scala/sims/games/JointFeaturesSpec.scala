package sims.games

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.dynamics.joints.*
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep, Solver}

/** Joint limits, motors, springs, the weld, wheel and motor joints, reactions and breaking. */
class JointFeaturesSpec extends AnyFunSuite with Matchers:
  private def world(solver: Solver): World =
    val w = World()
    w.solver = solver
    w.enableCollisionDetection = false
    w

  private def pivot(world: World, at: Vector2D): Body =
    val p = Circle(0.05).asBody
    p.pos = at
    p.fixed = true
    world += p
    p

  /** A horizontal rod of length 2 and 1 kg per m^2 from `from` to the right. */
  private def rod(world: World, from: Vector2D): Body =
    val r = Rectangle(1, 0.05).asBody
    r.pos = from + Vector2D(1, 0)
    world += r
    r

  test("a revolute joint's limits hold a falling rod at its lower angle, under both steps") {
    for solver <- Seq[Solver](ClassicStep, SoftStep()) do
      val w = world(solver)
      val top = pivot(w, Vector2D(0, 0))
      val arm = rod(w, Vector2D(0, 0))
      val hinge = RevoluteJoint(top, arm, Vector2D(0, 0))
      hinge.limits = Some(JointLimits(-0.3, 0.3))
      w += hinge
      var lowest = 0.0
      for _ <- 1 to 180 do
        w.step()
        lowest = math.min(lowest, hinge.angle)
      withClue(solver.toString) {
        lowest should be > -0.33
        hinge.angle shouldBe -0.3 +- 0.01
        hinge.separation should be < 0.01
      }
  }

  test("without limits the same rod swings far past them (the limits did the holding)") {
    val w = world(SoftStep())
    val hinge = RevoluteJoint(pivot(w, Vector2D.Zero), rod(w, Vector2D.Zero), Vector2D.Zero)
    w += hinge
    for _ <- 1 to 60 do w.step()
    hinge.angle should be < -1.0
  }

  test("a revolute joint's motor drives a wheel at its speed, or with its largest torque") {
    val w = world(SoftStep())
    w.gravity = Vector2D.Zero
    val axle = pivot(w, Vector2D.Zero)
    val wheel = Circle(0.5).asBody
    w += wheel
    val hinge = RevoluteJoint(axle, wheel, Vector2D.Zero)
    hinge.motor = Some(JointMotor(speed = 3, maxForce = 1000))
    w += hinge
    for _ <- 1 to 30 do w.step()
    wheel.angularVelocity shouldBe 3.0 +- 1e-6
    hinge.reactionTorque shouldBe 0.0 +- 1e-3 // at speed: no torque needed
    // A weak motor: the torque limits the acceleration, w = tau t / I.
    hinge.motor = Some(JointMotor(speed = -100, maxForce = 0.1))
    val w0 = wheel.angularVelocity
    for _ <- 1 to 60 do w.step()
    wheel.angularVelocity shouldBe (w0 - 0.1 * 1.0 / wheel.I) +- 1e-3
    hinge.reactionTorque shouldBe -0.1 +- 1e-9
  }

  test("a revolute joint's spring pulls the angle back and, damped, settles it at 0") {
    val w = world(SoftStep())
    w.gravity = Vector2D.Zero
    val hinge = RevoluteJoint(pivot(w, Vector2D.Zero), rod(w, Vector2D.Zero), Vector2D.Zero)
    hinge.spring = Some(JointSpring(hertz = 2, dampingRatio = 1))
    w += hinge
    hinge.node2.angularVelocity = 2
    var largest = 0.0
    for _ <- 1 to 240 do
      w.step()
      largest = math.max(largest, hinge.angle)
    largest should be > 0.02
    math.abs(hinge.angle) should be < 1e-3
  }

  test("a prismatic joint's limits stop a sliding box at the lower end, under both steps") {
    for solver <- Seq[Solver](ClassicStep, SoftStep()) do
      val w = world(solver)
      val base = pivot(w, Vector2D(0, 0))
      val box = Rectangle(0.2, 0.2).asBody
      box.pos = Vector2D(0, 0)
      w += box
      val slider = PrismaticJoint(base, Vector2D(0, 0), box, Vector2D(0, 1)) // the axis points up
      // Its anchor starts 1 m along the line; the box falls until it is at 0.
      slider.limits = Some(JointLimits(0, 2))
      w += slider
      for _ <- 1 to 120 do w.step()
      withClue(solver.toString) {
        slider.translation shouldBe 0.0 +- 0.01
        box.pos.y shouldBe -1.0 +- 0.01
        box.linearVelocity.length should be < 0.05
      }
  }

  test("a prismatic joint's motor lifts a box at its speed against gravity; its spring holds it") {
    val w = world(SoftStep())
    val base = pivot(w, Vector2D(0, 0))
    val box = Rectangle(0.2, 0.2).asBody
    w += box
    val lift = PrismaticJoint(base, Vector2D(0, 0), box, Vector2D(0, 1))
    lift.motor = Some(JointMotor(speed = 0.5, maxForce = 100))
    w += lift
    for _ <- 1 to 60 do w.step()
    box.linearVelocity.y shouldBe 0.5 +- 1e-3
    lift.translationSpeed shouldBe 0.5 +- 1e-3
    box.pos.y shouldBe 0.5 +- 0.02
    // The motor holds the weight: its force is m g along the axis.
    lift.reactionForce.y shouldBe box.mass * 9.81 +- 1e-3
    lift.motor = None
    lift.spring = Some(JointSpring(hertz = 1, dampingRatio = 1))
    for _ <- 1 to 600 do w.step()
    // Sagging below the rest position by m g / k, k = m (2 pi f)^2.
    lift.translation - lift.initialTranslation shouldBe (-9.81 / math.pow(2 * math.Pi, 2)) +- 0.01
  }

  test("a rigid weld holds a cantilever level under both steps; a soft one sags and springs") {
    for solver <- Seq[Solver](ClassicStep, SoftStep()) do
      val w = world(solver)
      val wall = pivot(w, Vector2D(0, 0))
      val beam = rod(w, Vector2D(0, 0))
      val weld = WeldJoint(wall, beam, Vector2D(0, 0))
      w += weld
      for _ <- 1 to 120 do w.step()
      withClue(solver.toString) {
        math.abs(weld.angle) should be < 0.01
        weld.separation should be < 0.01
      }
    val w = world(SoftStep())
    val beam = rod(w, Vector2D(0, 0))
    val soft = WeldJoint(pivot(w, Vector2D(0, 0)), beam, Vector2D(0, 0), angularHertz = 1, dampingRatio = 0.5)
    w += soft
    for _ <- 1 to 120 do w.step()
    soft.angle should be < -0.05
    soft.reactionForce.y shouldBe beam.mass * 9.81 +- 0.2
  }

  test("a wheel joint's suspension sags under the wheel's weight and its motor turns the wheel") {
    val w = world(SoftStep())
    val chassis = pivot(w, Vector2D(0, 0))
    val wheel = Circle(0.4).asBody
    wheel.pos = Vector2D(1, -0.5)
    w += wheel
    val joint = WheelJoint(chassis, wheel, wheel.pos, Vector2D(0, 1))
    joint.spring = Some(JointSpring(hertz = 2, dampingRatio = 1))
    joint.motor = Some(JointMotor(speed = -5, maxForce = 50))
    w += joint
    for _ <- 1 to 240 do w.step()
    // Sag m g / k with k = m (2 pi f)^2, along the axis only.
    joint.translation shouldBe (-9.81 / math.pow(4 * math.Pi, 2)) +- 0.005
    wheel.pos.x shouldBe 1.0 +- 1e-3
    wheel.angularVelocity shouldBe -5.0 +- 1e-3
    joint.limits = Some(JointLimits(-0.01, 0.01))
    for _ <- 1 to 60 do w.step()
    joint.translation shouldBe -0.01 +- 0.003
  }

  test("a motor joint drives a body to its target offset and angle, within its force") {
    val w = world(SoftStep())
    w.gravity = Vector2D.Zero
    val anchor = pivot(w, Vector2D(0, 0))
    val puck = Circle(0.3).asBody
    puck.pos = Vector2D(3, 0)
    w += puck
    val drive = MotorJoint(anchor, puck, Some(Vector2D(0, 2)), Some(1.0), maxForce = 50, maxTorque = 50)
    w += drive
    for _ <- 1 to 300 do w.step()
    puck.pos.x shouldBe 0.0 +- 0.01
    puck.pos.y shouldBe 2.0 +- 0.01
    puck.rotation shouldBe 1.0 +- 0.01
    // Within its force: a weak motor joint is far from its target after a second.
    val w2 = world(SoftStep())
    w2.gravity = Vector2D.Zero
    val slow = Circle(0.3).asBody
    slow.pos = Vector2D(3, 0)
    w2 += slow
    w2 += MotorJoint(pivot(w2, Vector2D.Zero), slow, Some(Vector2D(0, 0)), maxForce = 0.01)
    for _ <- 1 to 60 do w2.step()
    slow.pos.x should be > 2.9
  }

  test("every joint reports its reaction: a hanging weight's pin carries its weight") {
    val w = world(SoftStep())
    val top = pivot(w, Vector2D(0, 0))
    val bob = Circle(0.2).asBody
    bob.pos = Vector2D(0, -1)
    w += bob
    val pin = RevoluteJoint(top, bob, Vector2D(0, 0))
    w += pin
    pin.reactionForce shouldBe Vector2D.Zero
    for _ <- 1 to 60 do w.step()
    pin.reactionForce.x shouldBe 0.0 +- 1e-6
    pin.reactionForce.y shouldBe bob.mass * 9.81 +- 1e-3
    val w2 = world(SoftStep())
    val bob2 = Circle(0.2).asBody
    bob2.pos = Vector2D(0, -1)
    w2 += bob2
    val rope = DistanceJoint(pivot(w2, Vector2D.Zero), Vector2D.Zero, bob2, bob2.pos)
    w2 += rope
    for _ <- 1 to 60 do w2.step()
    rope.reactionForce.y shouldBe bob2.mass * 9.81 +- 1e-3
  }

  test("a joint whose reaction exceeds its breakForce is removed and reported, once") {
    val w = world(SoftStep())
    val top = pivot(w, Vector2D(0, 0))
    val bob = Circle(0.2).asBody // 0.126 kg: 1.23 N
    bob.pos = Vector2D(0, -1)
    w += bob
    val strong = RevoluteJoint(top, bob, Vector2D(0, -0.5))
    strong.breakForce = 2
    val weak = DistanceJoint(top, Vector2D(0, 0), bob, bob.pos)
    weak.breakForce = 1e9
    w += strong
    for _ <- 1 to 10 do w.step()
    w.jointBreaks shouldBe empty
    strong.breakForce = 1
    w.step()
    w.jointBreaks.map(_.joint) shouldBe Seq(strong)
    w.jointBreaks.head.force.length should be > 1.0
    w.joints shouldBe empty
    w.step()
    w.jointBreaks shouldBe empty
    bob.linearVelocity.y should be < 0.0 // falling now
    intercept[IllegalArgumentException](weak.breakForce = 0).getMessage should include("breakForce")
  }

  test("a broken joint is put back when its step fails later") {
    var fail = false
    val w = new World:
      override def postStep(): Unit = if fail then throw IllegalStateException("hook")
    w.solver = SoftStep()
    val top = pivot(w, Vector2D(0, 0))
    val bob = Circle(0.2).asBody
    bob.pos = Vector2D(0, -1)
    w += bob
    val pin = RevoluteJoint(top, bob, Vector2D(0, 0))
    pin.breakForce = 0.5
    w += pin
    fail = true
    intercept[IllegalStateException](w.step())
    w.joints shouldBe Seq(pin)
    fail = false
    w.step()
    w.joints shouldBe empty
  }

  test("the classic step refuses what it cannot step, naming itself, on joining, switching and stepping") {
    val w = World()
    val a = pivot(w, Vector2D.Zero)
    val b = Circle(0.2).asBody
    w += b
    val hinge = RevoluteJoint(a, b, Vector2D.Zero)
    hinge.motor = Some(JointMotor(1, 1))
    val joining = intercept[IllegalArgumentException](w += hinge)
    joining.getMessage should (include("ClassicStep") and include("motor") and include("SoftStep"))
    intercept[IllegalArgumentException](w += MotorJoint(a, b)).getMessage should include("ClassicStep")
    intercept[IllegalArgumentException](w += WheelJoint(a, b, b.pos, Vector2D(0, 1))).getMessage should include("spring")
    w.solver = SoftStep()
    w += hinge
    intercept[IllegalArgumentException](w.solver = ClassicStep).getMessage should include("ClassicStep")
    w.solver shouldBe SoftStep()
    hinge.motor = None
    w.solver = ClassicStep
    hinge.spring = Some(JointSpring(1))
    intercept[IllegalStateException](w.step()).getMessage should include("spring")
    hinge.spring = None
    hinge.limits = Some(JointLimits(-1, 1))
    w.step() // limits are the classic step's too
  }

  test("bad limits, motors and springs are rejected naming the argument") {
    intercept[IllegalArgumentException](JointLimits(1, 0)).getMessage should include("lower")
    intercept[IllegalArgumentException](JointLimits(Double.NaN, 0)).getMessage should include("lower")
    intercept[IllegalArgumentException](JointMotor(1, -1)).getMessage should include("maxForce")
    intercept[IllegalArgumentException](JointMotor(Double.PositiveInfinity, 1)).getMessage should include("speed")
    intercept[IllegalArgumentException](JointSpring(0)).getMessage should include("hertz")
    intercept[IllegalArgumentException](JointSpring(1, -1)).getMessage should include("dampingRatio")
    val a = Circle(1).asBody
    val b = Circle(1).asBody
    intercept[IllegalArgumentException](WheelJoint(a, b, Vector2D.Zero, Vector2D.Zero)).getMessage should include("axis")
    intercept[IllegalArgumentException](WeldJoint(a, b, Vector2D.Zero, linearHertz = -1)).getMessage should include("linearHertz")
    intercept[IllegalArgumentException](MotorJoint(a, b, correctionFactor = 2)).getMessage should include("correctionFactor")
  }
