package sims.dynamics.joints

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.geometry.Vector2D

class RevoluteJointSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private def world(): World =
    val w = World()
    w.enableCollisionDetection = false
    w

  private def fixedPivot(at: Vector2D): Body =
    val pivot = Circle(0.05, 1).asBody
    pivot.pos = at
    pivot.fixed = true
    pivot

  /** A rod of the given length, `angle` from hanging straight down, with its upper end at `top`.
    * Its rotation is 0 as a body, whatever the angle (the shape carries the angle).
    */
  private def rod(top: Vector2D, length: Double, angle: Double, density: Double = 1): Body =
    val shape = Rectangle(0.04, length / 2, density)
    shape.rotation = angle
    val body = shape.asBody
    body.pos = top + Vector2D(math.sin(angle), -math.cos(angle)) * (length / 2)
    body

  /** Mechanical energy with the potential energy measured from height `floor`. */
  private def energy(bodies: Seq[Body], g: Double, floor: Double): Double =
    bodies.map { b =>
      val v = b.linearVelocity
      0.5 * b.mass *
        (v dot v) + 0.5 * b.I * b.angularVelocity * b.angularVelocity +
        b.mass * g *
        (b.pos.y - floor)
    }.sum

  test("a physical pendulum keeps its pin within 1e-3 m for 20 s and swings with period 2 pi sqrt(I_pivot / (m g d)) to 1%") {
    // Pivots from the end of the rod to near its centre: d from length / 2 down to length / 10.
    forAll(Gen.choose(0.3, 2.0), Gen.choose(0.1, 0.5), minSuccessful(6)) { (length, pivotFraction) =>
      val w = world()
      val amplitude = 0.05
      val d = pivotFraction * length
      val pivotPoint = Vector2D(0, 0)
      val body = rod(pivotPoint + Vector2D(-math.sin(amplitude), math.cos(amplitude)) * (length / 2 - d), length, amplitude)
      val pivot = fixedPivot(pivotPoint)
      w += pivot
      w += body
      val pin = RevoluteJoint(pivot, body, pivotPoint)
      w += pin
      (body.pos - pivotPoint).length shouldBe d +- 1e-12

      val g = -w.gravity.y
      val expected = 2 * math.Pi * math.sqrt((body.I + body.mass * d * d) / (body.mass * g * d))
      var worstPin = 0.0
      // Times at which the centre of mass crosses below the pivot moving to the left.
      val crossings = collection.mutable.ArrayBuffer.empty[Double]
      var previousX = body.pos.x
      while w.time < 20 do
        w.step()
        worstPin = math.max(worstPin, pin.separation)
        val x = body.pos.x
        if previousX > 0 && x <= 0 then
          crossings += w.time - w.timeStep * x / (x - previousX)
        previousX = x
      val period = (crossings.last - crossings.head) / (crossings.length - 1)
      info(f"length $length%.2f, d $d%.3f: pin error $worstPin%.2e m, period $period%.5f s, expected $expected%.5f s, error ${(period /
          expected - 1) * 100}%.3f %%")
      worstPin should be < 1e-3
      crossings.length should be >= 3
      period shouldBe expected +- 0.01 * expected
    }
  }

  test("a double pendulum never gains more than 1% of its energy over 10 s and stays finite") {
    forAll(Gen.choose(0.3, math.Pi), Gen.choose(-math.Pi, math.Pi), Gen.choose(0.5, 3.0), minSuccessful(8)) {
      (angle1, angle2, density2) =>
        val w = world()
        val length = 1.0
        val pivot = fixedPivot(Vector2D(0, 0))
        val upper = rod(Vector2D(0, 0), length, angle1)
        val elbow = Vector2D(math.sin(angle1), -math.cos(angle1)) * length
        val lower = rod(elbow, length, angle2, density2)
        Seq(pivot, upper, lower).foreach(w += _)
        val joints = Seq(RevoluteJoint(pivot, upper, Vector2D(0, 0)), RevoluteJoint(upper, lower, elbow))
        joints.foreach(w += _)
        val g = -w.gravity.y
        val floor = -2 * length // no centre of mass ever gets this low
        val start = energy(Seq(upper, lower), g, floor)
        var highest = start
        var worstPin = 0.0
        while w.time < 10 do
          w.step()
          highest = math.max(highest, energy(Seq(upper, lower), g, floor))
          worstPin = math.max(worstPin, joints.map(_.separation).max)
        val end = energy(Seq(upper, lower), g, floor)
        info(f"angles ($angle1%.2f, $angle2%.2f): energy at most ${(highest / start - 1) *
            100}%.3f %% above the start, ${(end / start - 1) * 100}%.2f %% at the end; pin error $worstPin%.1e m")
        Seq(upper, lower).foreach(b => b.pos.isFinite shouldBe true)
        highest should be <= 1.01 * start
        worstPin should be < 1e-3
    }
  }

  test("two free bodies thrown and spinning under gravity stay pinned") {
    forAll(Gen.choose(-8.0, 8.0), Gen.choose(-8.0, 8.0), minSuccessful(5)) { (spin1, spin2) =>
      val w = world()
      val a = Rectangle(0.5, 0.1, 1).asBody
      val b = Circle(0.2, 4).asBody
      b.pos = Vector2D(0.7, 0.1)
      w += a
      w += b
      val pin = RevoluteJoint(a, b, Vector2D(0.45, 0.05))
      w += pin
      a.angularVelocity = spin1
      b.angularVelocity = spin2
      b.linearVelocity = Vector2D(2, 5)
      var worst = 0.0
      for _ <- 1 to 300 do
        w.step()
        worst = math.max(worst, pin.separation)
      worst should be < 1e-6
    }
  }

  test("one velocity correction makes the pin points' relative velocity zero") {
    val a = Rectangle(0.5, 0.2, 1).asBody
    val b = Rectangle(0.3, 0.3, 2).asBody
    b.pos = Vector2D(0.8, 0.3)
    val pin = RevoluteJoint(a, b, Vector2D(0.5, 0.1))
    a.linearVelocity = Vector2D(1, -2)
    a.angularVelocity = 3
    b.angularVelocity = -1
    val momentum = a.linearVelocity * a.mass + b.linearVelocity * b.mass
    pin.correctVelocity(1.0 / 60)
    val relative = b.velocityOfPoint(pin.connection2) - a.velocityOfPoint(pin.connection1)
    relative.length should be < 1e-12
    val after = a.linearVelocity * a.mass + b.linearVelocity * b.mass
    (after - momentum).length should be < 1e-12
  }

  test("position correction closes an opened pin; a fixed body does not move") {
    val ground = fixedPivot(Vector2D(0, 0))
    val b = Rectangle(0.5, 0.1, 1).asBody
    b.pos = Vector2D(0.5, 0)
    val pin = RevoluteJoint(ground, b, Vector2D(0, 0))
    b.pos = Vector2D(0.6, -0.15)
    b.rotation = 0.3
    for _ <- 1 to 10 do pin.correctPosition(1.0 / 60)
    pin.separation should be < 1e-9
    ground.pos shouldBe Vector2D(0, 0)
    ground.rotation shouldBe 0.0
    b.linearVelocity shouldBe Vector2D.Null
  }

  test("between two fixed bodies nothing is corrected and nothing breaks") {
    val a = fixedPivot(Vector2D(0, 0))
    val b = fixedPivot(Vector2D(1, 0))
    val pin = RevoluteJoint(a, b, Vector2D(0.5, 0))
    b.pos = Vector2D(2, 0)
    pin.correctVelocity(1.0 / 60)
    pin.correctPosition(1.0 / 60)
    a.pos shouldBe Vector2D(0, 0)
    b.pos shouldBe Vector2D(2, 0)
  }

  test("regression: a pin torn wide open gets bounded impulses, not the near-singular momentum-conserving ones") {
    // The impulses act at the middle of the two pin points; when the pin is torn open the matrix
    // of that solve can be nearly singular. This configuration makes its determinant 1.5e-5 of
    // the textbook K's; the joint must fall back to the textbook impulses.
    val a = Rectangle(0.5, 0.1, 1).asBody
    val b = Rectangle(0.5, 0.1, 1).asBody
    b.pos = Vector2D(1, 0)
    val pin = RevoluteJoint(a, b, Vector2D(0.5, 0))
    b.pos = Vector2D(-0.1921393940009657, 0.505236019974902)
    b.rotation = -1.591407096338666
    b.linearVelocity = Vector2D(0.3, -0.7)
    b.angularVelocity = 1.5
    val relativeSpeed = (b.velocityOfPoint(pin.connection2) - a.velocityOfPoint(pin.connection1)).length
    pin.correctVelocity(1.0 / 60)
    for body <- Seq(a, b) do
      body.linearVelocity.length should be < 10 * relativeSpeed
      math.abs(body.angularVelocity) should be < 100 * relativeSpeed
    (b.velocityOfPoint(pin.connection2) - a.velocityOfPoint(pin.connection1)).length should be < 1e-9
  }

  test("bad input is rejected with the argument's name") {
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    def message(f: => Any): String = intercept[IllegalArgumentException](f).getMessage
    message(RevoluteJoint(a, a, Vector2D(0, 0))) should include("two different bodies")
    message(RevoluteJoint(a, b, Vector2D(Double.NaN, 0))) should include("anchor")
    message(RevoluteJoint(a, b, Vector2D(0, Double.NegativeInfinity))) should include("anchor")
    message(RevoluteJoint(null, b, Vector2D(0, 0))) should include("node1")
    message(RevoluteJoint(a, null, Vector2D(0, 0))) should include("node2")
  }

  test("stepping a world with a joint whose body is not in it fails") {
    val w = world()
    val a = Circle(0.1, 1).asBody
    val b = Circle(0.1, 1).asBody
    w += a
    w += RevoluteJoint(a, b, Vector2D(0, 0))
    intercept[IllegalArgumentException](w.step()).getMessage should include("not in this world")
  }
