package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import sims.solver.{ClassicStep, SoftStep}

/** The Bullet scene: under the classic step every ordinary ball crosses its thin wall, under the
  * soft step some; the bullets never do, under either.
  */
class BulletSpec extends AnyFunSuite with Matchers:

  for solver <- Seq(ClassicStep, SoftStep()) do
    test(s"$solver: the bullets never cross their wall; the ordinary balls do") {
      val staged = Bullet.build()
      val world = staged.world.asInstanceOf[Bullet.CannonWorld]
      world.solver = solver
      for _ <- 1 to 240 do
        world.step()
        Bullet.crossed(world.bullets) shouldBe 0
      world.bullets.size shouldBe Bullet.Shots
      world.ordinary.size shouldBe Bullet.Shots
      val crossed = Bullet.crossed(world.ordinary)
      info(s"ordinary balls through: $crossed of ${Bullet.Shots}")
      // Under the soft step a few cross too: balls set spinning fast by the others (see
      // ContinuousCollisionSpec's spinning ball).
      if solver == ClassicStep then crossed shouldBe Bullet.Shots else crossed should be < Bullet.Shots
      // Every bullet went back from its wall.
      for b <- world.bullets do b.pos.x should be < Bullet.WallX
      val overlay = staged.overlay()
      overlay.highlighted shouldBe world.bullets.flatMap(_.shapes).toSet
      overlay.labels.map(_._2) shouldBe Seq(s"ordinary balls: $crossed of ${Bullet.Shots} through",
        s"bullets: 0 of ${Bullet.Shots} through")
    }
