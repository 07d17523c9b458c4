package sims.playground

import org.scalajs.dom
import sims.dynamics.{Body, Circle, Edge, RoundedSegment, Shape, World}
import sims.dynamics.joints.{DistanceJoint, Joint, MouseJoint, PrismaticJoint, RevoluteJoint, SpringJoint}
import sims.geometry.{ConvexPolygon, Vector2D}

/** Draws a world on a canvas: bodies filled by index (fixed ones grey), sensors dashed, a radius
  * line on circles so that their turning shows, and the joints.
  */
object Painter:
  private val Background = "#f7f7f2"
  private val FixedFill = "#9a9a9a"
  private val Palette = Seq("#e07a5f", "#3d85c6", "#81b29a", "#f2cc8f", "#9c6ade", "#5fb7c9", "#d4a373")
  private val JointColour = "#333333"
  private val DragColour = "#d62828"

  /** Clears the canvas and draws `world` as `view` shows it. */
  def paint(context: dom.CanvasRenderingContext2D, world: World, view: View): Unit =
    context.setLineDash(scala.scalajs.js.Array[Double]())
    context.fillStyle = Background
    context.fillRect(0, 0, view.width, view.height)
    var i = 0
    while i < world.bodies.length do
      drawBody(context, world.bodies(i), i, view)
      i += 1
    world.joints.foreach(drawJoint(context, _, view))

  private def drawBody(context: dom.CanvasRenderingContext2D, body: Body, index: Int, view: View): Unit =
    val fill = if body.fixed then FixedFill else Palette(index % Palette.length)
    for shape <- body.shapes do
      context.beginPath()
      outline(context, shape, view)
      if shape.sensor then context.setLineDash(scala.scalajs.js.Array(5.0, 3.0))
      else
        context.fillStyle = fill
        if !shape.isInstanceOf[Edge] then context.fill()
      context.strokeStyle = "#2b2b2b"
      context.lineWidth = if shape.isInstanceOf[Edge] then 2.5 else 1.0
      context.stroke()
      context.setLineDash(scala.scalajs.js.Array[Double]())
      shape match
        case circle: Circle =>
          val rim = circle.pos + Vector2D(circle.radius, 0).rotate(circle.rotation)
          line(context, circle.pos, rim, view)
        case _ => ()

  /** The shape's outline as a path: circles, convex polygons, capsules and edges; any other
    * shape (a user's own) by its bounding box.
    */
  private def outline(context: dom.CanvasRenderingContext2D, shape: Shape, view: View): Unit = shape match
    case circle: Circle =>
      context.arc(view.pixelX(circle.pos.x), view.pixelY(circle.pos.y), circle.radius * view.scale, 0, 2 * math.Pi)
    case edge: Edge =>
      context.moveTo(view.pixelX(edge.vertex1.x), view.pixelY(edge.vertex1.y))
      context.lineTo(view.pixelX(edge.vertex2.x), view.pixelY(edge.vertex2.y))
    case capsule: RoundedSegment =>
      val (start, end) = (capsule.vertex1, capsule.vertex2)
      // The canvas's y points down: angles there are the world's, negated.
      val direction = -math.atan2(end.y - start.y, end.x - start.x)
      val r = capsule.radius * view.scale
      context.arc(view.pixelX(end.x), view.pixelY(end.y), r, direction - math.Pi / 2, direction + math.Pi / 2)
      context.arc(view.pixelX(start.x), view.pixelY(start.y), r, direction + math.Pi / 2, direction + 3 * math.Pi / 2)
      context.closePath()
    case polygon: ConvexPolygon =>
      val vertices = polygon.vertices
      context.moveTo(view.pixelX(vertices(0).x), view.pixelY(vertices(0).y))
      for v <- vertices.tail do context.lineTo(view.pixelX(v.x), view.pixelY(v.y))
      context.closePath()
    case other =>
      val box = other.AABB
      context.rect(view.pixelX(box.minVertex.x), view.pixelY(box.maxVertex.y),
        (box.maxVertex.x - box.minVertex.x) * view.scale, (box.maxVertex.y - box.minVertex.y) * view.scale)

  private def line(context: dom.CanvasRenderingContext2D, from: Vector2D, to: Vector2D, view: View): Unit =
    context.beginPath()
    context.moveTo(view.pixelX(from.x), view.pixelY(from.y))
    context.lineTo(view.pixelX(to.x), view.pixelY(to.y))
    context.stroke()

  private def drawJoint(context: dom.CanvasRenderingContext2D, joint: Joint, view: View): Unit =
    context.strokeStyle = JointColour
    context.lineWidth = 1.5
    joint match
      case distance: DistanceJoint => line(context, distance.connection1, distance.connection2, view)
      case spring: SpringJoint =>
        context.setLineDash(scala.scalajs.js.Array(3.0, 2.0))
        line(context, spring.connection1, spring.connection2, view)
        context.setLineDash(scala.scalajs.js.Array[Double]())
      case revolute: RevoluteJoint =>
        val p = revolute.connection1
        context.beginPath()
        context.arc(view.pixelX(p.x), view.pixelY(p.y), 3.5, 0, 2 * math.Pi)
        context.stroke()
      case prismatic: PrismaticJoint => line(context, prismatic.connection1, prismatic.connection2, view)
      case mouse: MouseJoint =>
        context.strokeStyle = DragColour
        line(context, mouse.connection, mouse.target, view)
      case other =>
        context.setLineDash(scala.scalajs.js.Array(4.0, 4.0))
        line(context, other.node1.pos, other.node2.pos, view)
        context.setLineDash(scala.scalajs.js.Array[Double]())
