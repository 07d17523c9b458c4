package sims.dynamics.joints

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Body, Circle, Rectangle}
import sims.geometry.Vector2D

/** The worked examples of the documentation (4.4 and 4.6), driven through DistanceJoint: a rod
  * of length 1 between the origin (a fixed body) and the constrained point.
  */
class WorkedExamplesSpec extends AnyFunSuite with Matchers:

  private def origin(): Body =
    val b = Circle(0.01, 1).asBody
    b.fixed = true
    b

  test("4.4: a particle on the unit circle gets the impulse (-0.3, 0)") {
    val particle = Circle(0.1, 1 / (math.Pi * 0.01)).asBody // m = 1 kg
    particle.mass shouldBe 1.0 +- 1e-15
    particle.pos = Vector2D(1, 0)
    particle.linearVelocity = Vector2D(0.3, 2)
    val rod = DistanceJoint(origin(), Vector2D.Null, particle, Vector2D(1, 0))
    val before = particle.linearVelocity
    rod.correctVelocity(1.0 / 60)
    val impulse = (particle.linearVelocity - before) * particle.mass
    impulse.x shouldBe -0.3 +- 1e-12
    impulse.y shouldBe 0.0 +- 1e-12
    particle.linearVelocity.x shouldBe 0.0 +- 1e-12
    particle.linearVelocity.y shouldBe 2.0 +- 1e-12
  }

  test("4.6: a body on the unit circle, constrained at the point (1, 0) with r = (0.1, 0.2)") {
    // m = 1 and I = 1: a square of half side sqrt(1.5) and density 1/6.
    val body = Rectangle(math.sqrt(1.5), math.sqrt(1.5), 1.0 / 6).asBody
    body.mass shouldBe 1.0 +- 1e-15
    body.I shouldBe 1.0 +- 1e-15
    body.pos = Vector2D(0.9, -0.2) // so that r = x - pos = (0.1, 0.2)
    body.linearVelocity = Vector2D(0.3, 2)
    body.angularVelocity = 2
    val point = Vector2D(1, 0)
    val pointVelocity = body.velocityOfPoint(point)
    pointVelocity.x shouldBe -0.1 +- 1e-12
    pointVelocity.y shouldBe 2.2 +- 1e-12

    val rod = DistanceJoint(origin(), Vector2D.Null, body, point)
    rod.correctVelocity(1.0 / 60)

    val lambda = 0.1 / 1.04 // J M^-1 J^T = 1 + 0.2^2 = 1.04
    body.linearVelocity.x shouldBe 0.3 + lambda +- 1e-12
    body.linearVelocity.y shouldBe 2.0 +- 1e-12
    body.angularVelocity shouldBe 2 - 0.2 * lambda +- 1e-12
    val corrected = body.velocityOfPoint(point)
    corrected.x shouldBe 0.0 +- 1e-12
    corrected.y shouldBe 2 + 0.1 * body.angularVelocity +- 1e-12
    // The values as the documentation prints them, rounded.
    lambda shouldBe 0.096 +- 0.0005
    body.linearVelocity.x shouldBe 0.396 +- 0.0005
    body.angularVelocity shouldBe 1.98 +- 0.005
    corrected.y shouldBe 2.198 +- 0.0005
  }
