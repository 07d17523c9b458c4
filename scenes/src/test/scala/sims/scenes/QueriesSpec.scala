package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The Queries scene: its beam is the world's ray casts, its highlights a box query, and the
  * beam pushes what it hits.
  */
class QueriesSpec extends AnyFunSuite with Matchers:

  test("the beam starts at the emitter, ends its pieces on the shapes hit and reflects off them") {
    val staged = Queries.build()
    val world = staged.world
    for step <- 1 to 240 do
      world.step()
      if step % 20 == 0 then
        val pieces = Queries.beam(world)
        pieces.head._1.vertex1 shouldBe Queries.Emitter
        pieces.size should be <= Queries.Bounces + 1
        for ((segment, hit), next) <- pieces.zip(pieces.drop(1).map(Some(_)) :+ None) do
          hit.foreach { h =>
            // The piece ends where the shape's own cast from its start enters the shape.
            h.shape.rayCast(segment.vertex1, segment.vertex1 + (h.point - segment.vertex1) * 2).map(_.point.x)
              .getOrElse(Double.NaN) shouldBe h.point.x +- 1e-9
            next.foreach { (reflected, _) =>
              val in = segment.d.unit
              val out = reflected.d.unit
              (out dot h.normal) shouldBe -(in dot h.normal) +- 1e-9 // the angle of reflection
            }
          }
        staged.overlay().lines shouldBe pieces.map(_._1)
  }

  test("the highlights are the free shapes whose bounds overlap the sweeping box, as brute force finds them") {
    val staged = Queries.build()
    val world = staged.world
    var seen = 0
    for step <- 1 to 300 do
      world.step()
      val zone = Queries.zone(world.time)
      val expected = world.shapes.filter(s => !s.body.fixed && s.AABB.overlaps(zone)).toSet
      staged.overlay().highlighted shouldBe expected
      staged.overlay().boxes shouldBe Seq(zone)
      seen += expected.size
    seen should be > 0
  }

  test("the beam pushes the first free body it hits, along itself, never more than half its weight") {
    val world = Queries.build().world
    var pushes = 0
    for _ <- 1 to 300 do
      world.step() // the push is applied after the step, for the next one
      Queries.beam(world).headOption.flatMap(_._2).filter(!_.shape.body.fixed).foreach { hit =>
        val body = hit.shape.body
        val expected = Queries.direction(world.time) * (Queries.Push * body.mass)
        body.force.x shouldBe expected.x +- 1e-9
        body.force.y shouldBe expected.y +- 1e-9
        expected.length should be < body.mass * 9.81 / 2 + 1e-9
        pushes += 1
      }
    pushes should be > 10
  }
