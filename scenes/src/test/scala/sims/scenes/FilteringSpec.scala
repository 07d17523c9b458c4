package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.dynamics.{Capsule, Shape}
import sims.solver.{ClassicStep, SoftStep}

/** The Filtering scene under both steps: its filtered pairs never touch, and the two streams
  * pass each other.
  */
class FilteringSpec extends AnyFunSuite with Matchers:

  private def category(s: Shape): Int = s.categoryBits

  for solver <- Seq(ClassicStep, SoftStep()) do
    test(s"$solver: balls and boxes never touch, nor the capsules each other, nor the arm its post; the streams cross") {
      val world = Filtering.build().world
      world.solver = solver
      val balls = world.shapes.filter(category(_) == Filtering.BallCategory)
      val boxes = world.shapes.filter(category(_) == Filtering.BoxCategory)
      balls.size shouldBe 10
      boxes.size shouldBe 10
      val hinged = world.joints.head
      for _ <- 1 to 180 do
        world.step()
        for c <- world.contacts do
          Set(category(c.shape1), category(c.shape2)) should not be Set(Filtering.BallCategory, Filtering.BoxCategory)
          (c.shape1.isInstanceOf[Capsule] && c.shape2.isInstanceOf[Capsule]) shouldBe false
          Set(c.shape1.body, c.shape2.body) should not be Set(hinged.node1, hinged.node2)
      // The balls started left of every box and moving right; now most are right of most.
      def mean(shapes: Seq[Shape]) = shapes.map(_.pos.x).sum / shapes.size
      mean(balls) should be > mean(boxes)
    }
