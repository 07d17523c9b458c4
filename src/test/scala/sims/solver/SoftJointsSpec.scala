package sims.solver

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.dynamics.joints.{DistanceJoint, MouseJoint, PrismaticJoint, RevoluteJoint, SpringJoint}
import sims.geometry.Vector2D

/** Every joint under the soft step, solved directly (joint trees) and iteratively. */
class SoftJointsSpec extends AnyFunSuite with Matchers:

  private def world(direct: Boolean): World =
    val w = World()
    w.enableCollisionDetection = false
    w.solver = SoftStep(directJoints = direct)
    w

  private def fixedBox(): Body =
    val body = Rectangle(1, 0.1, 1).asBody
    body.fixed = true
    body

  test("a slider on a fixed 30-degree line accelerates at g sin(30 deg) and stays on the line") {
    for direct <- Seq(true, false) do
      val w = world(direct)
      val rail = fixedBox()
      val slope = math.toRadians(30)
      val direction = Vector2D(math.cos(slope), math.sin(slope))
      val slider = Rectangle(0.2, 0.1, 3).asBody
      slider.pos = direction * 2
      w += rail
      w += slider
      val sliding = slider.pos + Vector2D(0.05, 0.1)
      val joint = PrismaticJoint(rail, sliding - direction * 2, slider, sliding)
      w += joint
      var worstLine, worstAngle = 0.0
      val speeds = collection.mutable.ArrayBuffer.empty[Double]
      for _ <- 1 to 120 do
        w.step()
        speeds += (slider.linearVelocity dot joint.axis)
        worstLine = math.max(worstLine, joint.lineError)
        worstAngle = math.max(worstAngle, math.abs(joint.angleError))
      val acceleration = -(speeds(119) - speeds(59)) / (60 * w.timeStep)
      val expected = 9.81 * math.sin(slope)
      info(
        f"direct = $direct: acceleration $acceleration%.6f m/s^2 (expected $expected%.6f), line error $worstLine%.1e m, angle error $worstAngle%.1e rad")
      acceleration shouldBe expected +- 1e-3 * expected
      worstLine should be < 1e-4
      worstAngle should be < 1e-4
  }

  test("a revolute pendulum keeps its pin closed and swings with the period of a physical pendulum") {
    for direct <- Seq(true, false) do
      val w = world(direct)
      val pivot = fixedBox()
      val rod = Rectangle(0.5, 0.05, 1).asBody
      rod.pos = Vector2D(0.5, 0)
      w += pivot
      w += rod
      val joint = RevoluteJoint(pivot, rod, Vector2D(0, 0))
      w += joint
      // Released horizontally; small-amplitude theory does not apply, so compare with the
      // exact period of a physical pendulum released at 90 degrees: T = 4 sqrt(I_p / (m g d)) K(sin 45 deg).
      val crossings = collection.mutable.ArrayBuffer.empty[Double]
      var previousX = rod.pos.x
      var worstPin = 0.0
      for _ <- 1 to 600 do
        w.step()
        worstPin = math.max(worstPin, joint.separation)
        // The crossing time interpolated within the step (steps are 17 ms, the period 2 s).
        if previousX > 0 && rod.pos.x <= 0 || previousX < 0 && rod.pos.x >= 0 then
          crossings += w.time - w.timeStep * rod.pos.x / (rod.pos.x - previousX)
        previousX = rod.pos.x
      val period = 2 * (crossings(2) - crossings(1))
      val inertia = rod.I + rod.mass * 0.25
      val k = 1.8540746773013719 // K(1 / sqrt 2), the complete elliptic integral of the first kind
      val expected = 4 * math.sqrt(inertia / (rod.mass * 9.81 * 0.5)) * k
      info(f"direct = $direct: period $period%.4f s (exact $expected%.4f s), pin open at most $worstPin%.1e m")
      period shouldBe expected +- 0.005 * expected
      worstPin should be < (if direct then 1e-3 else 1e-2)
  }

  test("a mouse joint drags a body to its target, its force within maxForce") {
    for heavy <- Seq(false, true) do
      val w = world(direct = true)
      w.gravity = Vector2D.Null
      val body = Circle(0.3, if heavy then 50 else 0.5).asBody
      w += body
      val maxForce = 200 * body.mass
      val joint = MouseJoint(body, body.pos, maxForce)
      w += joint
      joint.target = Vector2D(2, 1)
      var largest = 0.0
      var previous = body.linearVelocity
      for _ <- 1 to 180 do
        w.step()
        largest = math.max(largest, ((body.linearVelocity - previous) * body.mass / w.timeStep).length)
        previous = body.linearVelocity
      info(
        f"heavy = $heavy: at ${(body.pos - Vector2D(2, 1)).length}%.2e m from the target, largest force ${largest / maxForce}%.3f maxForce")
      (body.pos - Vector2D(2, 1)).length should be < 1e-3
      largest should be <= maxForce * (1 + 1e-9)
  }

  test("a spring oscillates with its period 2 pi sqrt(m / k), its force applied in every substep") {
    val w = world(direct = true)
    w.gravity = Vector2D.Null
    val anchor = Circle(0.1, 1).asBody
    anchor.fixed = true
    val ball = Circle(0.1, 1).asBody
    ball.pos = Vector2D(1, 0)
    w += anchor
    w += ball
    val k = 5.0
    w += SpringJoint(anchor, anchor.pos, ball, ball.pos, k, 0.8)
    val crossings = collection.mutable.ArrayBuffer.empty[Double]
    var previous = ball.pos.x - 0.8
    for _ <- 1 to 600 do
      w.step()
      val now = ball.pos.x - 0.8
      if previous > 0 && now <= 0 then crossings += w.time - w.timeStep * now / (now - previous)
      previous = now
    val period = crossings(2) - crossings(1)
    val expected = 2 * math.Pi * math.sqrt(ball.mass / k)
    info(f"period $period%.4f s, expected $expected%.4f s")
    period shouldBe expected +- 0.005 * expected
  }

  test("the joints follow their bodies' new indices when a body earlier in the world leaves between steps") {
    // A spring and a distance joint on bodies after `leaving`: once it leaves, their indices
    // move down one place; the step must apply the spring's force and solve the joint on the
    // bodies they join, as a world built without it does, to the bit.
    def build(withLeaving: Boolean): (World, Seq[Body], Option[Body]) =
      val w = world(direct = true)
      val leaving = Option.when(withLeaving)(Circle(0.1, 1).asBody)
      leaving.foreach(b => { b.pos = Vector2D(-5, 0); w += b })
      val anchor = Circle(0.1, 1).asBody
      anchor.fixed = true
      val ball = Circle(0.1, 1).asBody
      ball.pos = Vector2D(1, 0)
      val bob = Circle(0.1, 1).asBody
      bob.pos = Vector2D(1, -0.5)
      Seq(anchor, ball, bob).foreach(w += _)
      w += DistanceJoint(anchor, anchor.pos, ball, ball.pos)
      w += SpringJoint(ball, ball.pos, bob, bob.pos, 5.0, 0.3)
      (w, Seq(anchor, ball, bob), leaving)
    val (changed, bodies, leaving) = build(withLeaving = true)
    for _ <- 1 to 30 do changed.step()
    val (fresh, freshBodies, _) = build(withLeaving = false)
    for _ <- 1 to 30 do fresh.step()
    // The same start for both from here: the fresh world takes the changed one's state.
    for (b, f) <- bodies.zip(freshBodies) do
      f.pos = b.pos; f.rotation = b.rotation; f.linearVelocity = b.linearVelocity; f.angularVelocity = b.angularVelocity
    changed -= leaving.get
    for _ <- 1 to 60 do
      changed.step()
      fresh.step()
    for (b, f) <- bodies.zip(freshBodies) do
      b.pos shouldBe f.pos
      b.linearVelocity shouldBe f.linearVelocity
  }
