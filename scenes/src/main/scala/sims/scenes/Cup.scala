package sims.scenes

import sims.dynamics.{Body, Circle, Shape}
import sims.geometry.{PortableMath, Vector2D}

/** A fixed cup made of one body of circles in a U, and three balls dropped into it. */
object Cup extends Scene:
  private val CupRadius = 2.0
  private val BeadRadius = 0.15

  def name: String = "Cup"
  def description: String = "A fixed cup made of circles, three balls dropped into it."
  def view: Region = Region(-4, -3, 4, 4)
  override def region: Region = Region(-3, -2.5, 3, 6)

  def build(): Staged =
    // Beads on the lower half circle, close enough that no ball slips between them.
    val beadCount = 28
    val beads: Seq[Shape] =
      for i <- 0 to beadCount yield
        val angle = math.Pi + math.Pi * i / beadCount
        val bead = Circle(BeadRadius, 1)
        bead.pos = Vector2D(CupRadius * PortableMath.cos(angle), CupRadius * PortableMath.sin(angle))
        bead
    val cup = Body(beads*)
    cup.fixed = true
    val world = Scene.worldOf(cup)
    world += Scene.ball(Vector2D(-0.6, 1), 0.4)
    world += Scene.ball(Vector2D(0.3, 2.2), 0.5)
    world += Scene.ball(Vector2D(-0.1, 3.5), 0.3)
    Staged(world)
