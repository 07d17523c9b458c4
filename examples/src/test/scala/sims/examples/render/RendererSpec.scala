package sims.examples.render

import java.awt.Color
import java.awt.image.BufferedImage
import org.scalatest.funsuite.AnyFunSuite
import sims.dynamics.{Capsule, Edge, World}
import sims.scenes.{Region, Scene}
import sims.geometry.Vector2D

/** The renderer draws a known scene; pixels are checked where things are and where they are not. */
class RendererSpec extends AnyFunSuite:
  /** A 10 m x 10 m view at 20 px/m: ground from y = -1 to 0, a ball of radius 1 at (2, 3). */
  private def knownWorld(): World =
    val world = World()
    world += Scene.ground(5)
    world += Scene.ball(Vector2D(2, 3), 1)
    world
  private val viewport = Viewport.fit(Region(-5, -5, 5, 5), 200, 200)

  private def colourAt(image: BufferedImage, x: Double, y: Double): Color =
    Color(image.getRGB(viewport.pixelX(x).toInt, viewport.pixelY(y).toInt))

  test("ground, ball and background are where they should be"):
    val image = Renderer.image(knownWorld(), viewport)
    assert(image.getWidth == 200 && image.getHeight == 200)
    assert(colourAt(image, 0, -0.5) == Renderer.FixedFill, "inside the ground")
    assert(colourAt(image, -4, -0.6) == Renderer.FixedFill, "inside the ground, left")
    assert(colourAt(image, 2.3, 3.4) == Renderer.Palette(1), "inside the ball (body 1), off its radius line")
    for (x, y) <- Seq((-4.0, 4.0), (0.0, 2.0), (4.0, 1.0), (0.0, -3.0), (-2.0, 3.0)) do
      assert(colourAt(image, x, y) == Renderer.Background, s"background at ($x, $y)")

  test("the picture follows the bodies"):
    val world = knownWorld()
    world.bodies(1).pos = Vector2D(-2, 3)
    val image = Renderer.image(world, viewport)
    assert(colourAt(image, -1.7, 3.4) == Renderer.Palette(1))
    assert(colourAt(image, 2.3, 3.4) == Renderer.Background)

  test("the grid is drawn on its lines only when asked"):
    val world = knownWorld()
    // x = 4 is a multiple of the grid side 2; (4, 3) is empty space.
    val plain = Renderer.image(world, viewport)
    val gridded = Renderer.image(world, viewport, RenderOptions(grid = true))
    assert(colourAt(plain, 4, 3) == Renderer.Background)
    assert(colourAt(gridded, 4, 3) != Renderer.Background)
    assert(colourAt(gridded, 3, 1) == Renderer.Background, "between grid lines")

  test("contacts are drawn where the ball touches the ground"):
    val world = World()
    world += Scene.ground(5)
    world += Scene.ball(Vector2D(0, 0.98), 1)
    world.step()
    assert(world.contacts.nonEmpty)
    val contact = world.contacts.head.points.head
    val image = Renderer.image(world, viewport, RenderOptions(contacts = true))
    assert(colourAt(image, contact.x, contact.y) == Renderer.ContactColour)

  test("the soft step's contacts are drawn too, a speculative point (not touching yet) lighter"):
    def soft(height: Double): World =
      val world = World()
      world.solver = sims.solver.SoftStep()
      world += Scene.ground(5)
      world += Scene.ball(Vector2D(0, 1 + height), 1)
      world.step()
      world
    val hovering = soft(0.01) // 1 cm above the ground: within the speculative distance
    val speculative = hovering.contacts.head
    assert(speculative.separations.head > 0)
    val point = speculative.points.head
    val image = Renderer.image(hovering, viewport, RenderOptions(contacts = true))
    assert(colourAt(image, point.x, point.y) == Renderer.SpeculativeColour)
    val touching = soft(-0.02)
    assert(touching.contacts.head.separations.head <= 0)
    val pressed = touching.contacts.head.points.head
    assert(colourAt(Renderer.image(touching, viewport, RenderOptions(contacts = true)), pressed.x, pressed.y) ==
      Renderer.ContactColour)

  test("bounding boxes are drawn when asked"):
    val world = knownWorld()
    // The ball's box has corners at (1, 2) and (3, 4); its left side passes (1, 3.5).
    val image = Renderer.image(world, viewport, RenderOptions(boxes = true))
    val onBox = colourAt(image, 1, 3.5)
    assert(onBox != Renderer.Background && colourAt(Renderer.image(world, viewport), 1, 3.5) == Renderer.Background)

  test("capsules are drawn round-ended, edges as thick lines"):
    val world = World()
    val pill = Capsule(1.5, 1, 1)
    pill.pos = Vector2D(0, 2)
    world += pill.asBody
    world += Edge(Vector2D(-4, -2), Vector2D(4, -2)).asBody
    val image = Renderer.image(world, viewport, RenderOptions(smooth = false))
    assert(colourAt(image, 2.2, 2.2) == Renderer.Palette(0), "in the right round end")
    assert(colourAt(image, 2.4, 2.9) == Renderer.Background, "beyond the round end, inside the bounding box")
    assert(colourAt(image, -1, 2.9) == Renderer.Palette(0), "along the side")
    assert(colourAt(image, 0, -2) == Renderer.FixedFill.darker(), "on the edge")
    assert(colourAt(image, 0, -2.3) == Renderer.Background, "below the edge")

  test("a scene's overlay: lines, highlighted shapes and boxes"):
    val world = knownWorld()
    val ball = world.bodies(1).shapes.head
    val overlay = sims.scenes.Overlay(lines = Seq(sims.geometry.Segment(Vector2D(-4, 2), Vector2D(-1, 2))),
      highlighted = Set(ball), boxes = Seq(sims.geometry.AABB(Vector2D(-4, -4), Vector2D(-2, -3))))
    val image = Renderer.image(world, viewport, RenderOptions(smooth = false), overlay)
    assert(colourAt(image, -2.5, 2) == Renderer.LineColour, "on the line")
    assert(colourAt(image, 3, 3) == Renderer.HighlightColour, "on the ball's outline")
    assert(colourAt(image, -3.9, -3) == Renderer.HighlightColour, "on the box's top, where its dashes start")
    assert(colourAt(Renderer.image(world, viewport, RenderOptions(smooth = false)), -2.5, 2) == Renderer.Background)

  test("every scene renders without error at its own view"):
    for scene <- sims.scenes.Scenes.all do
      val world = scene.build().world
      val image = Renderer.image(world, Viewport.fit(scene.view, 160, 120),
        RenderOptions(contacts = true, boxes = true, grid = true, caption = scene.name))
      assert(image.getWidth == 160, scene.name)
