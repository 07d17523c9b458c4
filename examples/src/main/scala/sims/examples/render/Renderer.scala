package sims.examples.render

import java.awt.{BasicStroke, Color, Font, Graphics2D, RenderingHints}
import java.awt.geom.{Ellipse2D, Line2D, Path2D, Rectangle2D}
import java.awt.image.BufferedImage
import sims.collision.GridDetector
import sims.dynamics.{Body, Circle, Edge, RoundedSegment, Shape, World}
import sims.dynamics.joints.{DistanceJoint, Joint, MouseJoint, PrismaticJoint, RevoluteJoint, SpringJoint}
import sims.geometry.{ConvexPolygon, Vector2D}
import sims.scenes.Overlay

/** Draws a world onto a `Graphics2D` through a [[Viewport]]: bodies, joints and the overlays
  * chosen in [[RenderOptions]]. The headless runs (GIF, PNG) and the viewer share it, so what
  * the files show is what the window shows.
  */
object Renderer:
  /** Colour of the empty background. */
  val Background: Color = Color(0xf4f1ea)
  /** Fill colour of fixed bodies (ground, walls). */
  val FixedFill: Color = Color(0x7d7f85)
  /** Fill colours of free bodies, chosen by the body's index in the world. */
  val Palette: IndexedSeq[Color] =
    IndexedSeq(0xe4572e, 0x29335c, 0xf3a712, 0x17bebb, 0x669bbc, 0xa8c686, 0xc44569, 0x6a4c93).map(Color(_))
  /** Colour of joints. */
  val JointColour: Color = Color(0x30343f)
  /** Colour of prismatic joints' rails. */
  val RailColour: Color = Color(0xb0aa98)
  /** Colour of contact points and normals (and of the mouse's pull). */
  val ContactColour: Color = Color(0xd00000)
  /** Colour of the soft step's speculative contact points (shapes not touching yet). */
  val SpeculativeColour: Color = Color(0xf0a0a0)
  /** Colour of bounding boxes. */
  val BoxColour: Color = Color(0x2a9d8f)
  /** Colour of the broadphase grid. */
  val GridColour: Color = Color(0xd8d3c4)
  /** Colour of an overlay's lines (a scene's laser). */
  val LineColour: Color = Color(0xff1f4b)
  /** Colour of an overlay's highlighted shapes and marked boxes. */
  val HighlightColour: Color = Color(0xffd400)
  /** Every colour drawn without smoothing: the palette of the GIF frames. */
  val colours: IndexedSeq[Color] =
    (IndexedSeq(Background, FixedFill, FixedFill.darker(), JointColour, RailColour, ContactColour, SpeculativeColour,
      BoxColour, GridColour, LineColour, HighlightColour) ++ Palette ++ Palette.map(_.darker())).distinct

  /** Below this many pixels per grid cell the grid is not drawn (it would fill the picture). */
  private val MinimumCellPixels = 4.0

  /** A new RGB picture of the world as seen through `viewport`, with a scene's `overlay`. */
  def image(world: World, viewport: Viewport, options: RenderOptions = RenderOptions(),
      overlay: Overlay = Overlay.empty): BufferedImage =
    val picture = BufferedImage(viewport.width, viewport.height, BufferedImage.TYPE_INT_RGB)
    val g = picture.createGraphics()
    try draw(g, world, viewport, options, overlay)
    finally g.dispose()
    picture

  /** Draws the world over the whole viewport area of `g` (background first), then `overlay`. */
  def draw(g: Graphics2D, world: World, viewport: Viewport, options: RenderOptions = RenderOptions(),
      overlay: Overlay = Overlay.empty): Unit =
    if options.smooth then
      g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON)
      g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE)
    else
      g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF)
      g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_OFF)
    g.setColor(Background)
    g.fillRect(0, 0, viewport.width, viewport.height)
    if options.grid then drawGrid(g, world, viewport)
    val bodies = world.bodies
    var i = 0
    while i < bodies.length do
      drawBody(g, bodies(i), i, viewport)
      i += 1
    world.joints.foreach(drawJoint(g, _, viewport))
    drawOverlay(g, overlay, viewport)
    if options.boxes then world.shapes.foreach(drawBox(g, _, viewport))
    if options.contacts then drawContacts(g, world, viewport)
    if options.caption.nonEmpty then drawCaption(g, options.caption)

  /** Fill colour of the body at `index` in its world. */
  def fillOf(body: Body, index: Int): Color = if body.fixed then FixedFill else Palette(index % Palette.length)

  private def drawBody(g: Graphics2D, body: Body, index: Int, viewport: Viewport): Unit =
    val fill = fillOf(body, index)
    val outline = fill.darker()
    body.shapes.foreach { shape =>
      val outlinePath = shapePath(shape, viewport)
      // A sensor pushes nothing: its outline alone, dashed, so what passes through it shows.
      if !shape.sensor then
        g.setColor(fill)
        g.fill(outlinePath)
      g.setColor(outline)
      // An edge has no inside to fill: its line is drawn thicker.
      g.setStroke(
        if shape.sensor then BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, Array(5f, 3f), 0f)
        else BasicStroke(if shape.isInstanceOf[Edge] then 2.5f else 1f))
      g.draw(outlinePath)
      shape match
        case circle: Circle =>
          // A radius line shows how the circle turns.
          val edge = circle.pos + Vector2D(circle.radius, 0).rotate(circle.rotation)
          g.draw(line(circle.pos, edge, viewport))
        case _ => ()
    }

  /** The outline of a shape in pixels: circles, convex polygons, capsules and edges; any other
    * shape type (a user's own) is shown by its bounding box.
    */
  private def shapePath(shape: Shape, viewport: Viewport): java.awt.Shape = shape match
    case circle: Circle =>
      val r = circle.radius * viewport.scale
      Ellipse2D.Double(viewport.pixelX(circle.pos.x) - r, viewport.pixelY(circle.pos.y) - r, 2 * r, 2 * r)
    case edge: Edge => line(edge.vertex1, edge.vertex2, viewport)
    case capsule: RoundedSegment => capsulePath(capsule, viewport)
    case polygon: ConvexPolygon =>
      val path = Path2D.Double()
      val vertices = polygon.vertices
      path.moveTo(viewport.pixelX(vertices(0).x), viewport.pixelY(vertices(0).y))
      for v <- vertices.tail do path.lineTo(viewport.pixelX(v.x), viewport.pixelY(v.y))
      path.closePath()
      path
    case other => boxPath(other, viewport)

  /** A capsule's outline: a half circle around each end of its core, joined by its sides. */
  private def capsulePath(capsule: RoundedSegment, viewport: Viewport): Path2D =
    val path = Path2D.Double()
    val (start, end) = (capsule.vertex1, capsule.vertex2)
    val direction = math.atan2(end.y - start.y, end.x - start.x)
    val steps = 12 // per half circle
    for (centre, from) <- Seq((end, direction - math.Pi / 2), (start, direction + math.Pi / 2)); k <- 0 to steps do
      val angle = from + math.Pi * k / steps
      val p = centre + Vector2D(math.cos(angle), math.sin(angle)) * capsule.radius
      if centre == end && k == 0 then path.moveTo(viewport.pixelX(p.x), viewport.pixelY(p.y))
      else path.lineTo(viewport.pixelX(p.x), viewport.pixelY(p.y))
    path.closePath()
    path

  /** A scene's overlay: its boxes and highlighted shapes' outlines, then its lines and labels. */
  private def drawOverlay(g: Graphics2D, overlay: Overlay, viewport: Viewport): Unit =
    g.setColor(HighlightColour)
    g.setStroke(BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, Array(6f, 4f), 0f))
    for box <- overlay.boxes do
      val left = viewport.pixelX(box.minVertex.x)
      val top = viewport.pixelY(box.maxVertex.y)
      g.draw(Rectangle2D.Double(left, top, viewport.pixelX(box.maxVertex.x) - left, viewport.pixelY(box.minVertex.y) - top))
    g.setStroke(BasicStroke(3f))
    overlay.highlighted.foreach(shape => g.draw(shapePath(shape, viewport)))
    g.setColor(LineColour)
    g.setStroke(BasicStroke(2f))
    overlay.lines.foreach(segment => g.draw(line(segment.vertex1, segment.vertex2, viewport)))
    if overlay.labels.nonEmpty then
      g.setFont(Font(Font.SANS_SERIF, Font.BOLD, 13))
      g.setColor(JointColour)
      for (at, text) <- overlay.labels do g.drawString(text, viewport.pixelX(at.x).toFloat, viewport.pixelY(at.y).toFloat)

  private def boxPath(shape: Shape, viewport: Viewport): Rectangle2D =
    val box = shape.AABB
    val left = viewport.pixelX(box.minVertex.x)
    val top = viewport.pixelY(box.maxVertex.y)
    Rectangle2D.Double(left, top, viewport.pixelX(box.maxVertex.x) - left, viewport.pixelY(box.minVertex.y) - top)

  private def line(from: Vector2D, to: Vector2D, viewport: Viewport): Line2D =
    Line2D.Double(viewport.pixelX(from.x), viewport.pixelY(from.y), viewport.pixelX(to.x), viewport.pixelY(to.y))

  private def drawJoint(g: Graphics2D, joint: Joint, viewport: Viewport): Unit =
    g.setColor(JointColour)
    joint match
      case distance: DistanceJoint =>
        g.setStroke(BasicStroke(1.5f))
        g.draw(line(distance.connection1, distance.connection2, viewport))
      case spring: SpringJoint =>
        g.setStroke(BasicStroke(1f))
        g.draw(zigzag(spring.connection1, spring.connection2, viewport))
      case revolute: RevoluteJoint =>
        g.setStroke(BasicStroke(1.5f))
        val p = revolute.connection1
        val r = 3.5
        g.draw(Ellipse2D.Double(viewport.pixelX(p.x) - r, viewport.pixelY(p.y) - r, 2 * r, 2 * r))
      case prismatic: PrismaticJoint =>
        // The rail: from the anchor on node1 along the axis to the slider on node2.
        g.setStroke(BasicStroke(1f))
        g.setColor(RailColour)
        g.draw(line(prismatic.connection1, prismatic.connection2, viewport))
        val p = prismatic.connection2
        g.setColor(JointColour)
        g.draw(Rectangle2D.Double(viewport.pixelX(p.x) - 3, viewport.pixelY(p.y) - 3, 6, 6))
      case mouse: MouseJoint =>
        g.setStroke(BasicStroke(1.5f))
        g.setColor(ContactColour)
        g.draw(line(mouse.connection, mouse.target, viewport))
      case other =>
        // Joints without a drawing of their own: a dashed line between the two bodies.
        g.setStroke(BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, Array(4f, 4f), 0f))
        g.draw(line(other.node1.pos, other.node2.pos, viewport))

  /** A spring drawn as a zigzag of fixed pixel width between two points. */
  private def zigzag(from: Vector2D, to: Vector2D, viewport: Viewport): Path2D =
    val x1 = viewport.pixelX(from.x); val y1 = viewport.pixelY(from.y)
    val x2 = viewport.pixelX(to.x); val y2 = viewport.pixelY(to.y)
    val length = math.hypot(x2 - x1, y2 - y1)
    val path = Path2D.Double()
    path.moveTo(x1, y1)
    if length > 0 then
      val ux = (x2 - x1) / length; val uy = (y2 - y1) / length
      // About one tooth per 6 pixels, so short springs stay readable.
      val teeth = math.max(4, math.min(12, (length / 6).toInt))
      val amplitude = 3.0
      for k <- 1 until teeth do
        val t = length * k / teeth
        val side = if k % 2 == 0 then amplitude else -amplitude
        path.lineTo(x1 + ux * t - uy * side, y1 + uy * t + ux * side)
    path.lineTo(x2, y2)
    path

  private def drawBox(g: Graphics2D, shape: Shape, viewport: Viewport): Unit =
    g.setColor(BoxColour)
    g.setStroke(BasicStroke(1f))
    g.draw(boxPath(shape, viewport))

  /** The contacts of the solver's last step (`world.contacts`, either solver's): points and
    * normals; speculative points (the soft step's, separation above 0) in a lighter colour.
    */
  private def drawContacts(g: Graphics2D, world: World, viewport: Viewport): Unit =
    g.setStroke(BasicStroke(1.5f))
    val normalPixels = 14.0
    for contact <- world.contacts do
      val n = contact.normal
      for i <- contact.points.indices do
        val p = contact.points(i)
        g.setColor(if contact.separations(i) > 0 then SpeculativeColour else ContactColour)
        val px = viewport.pixelX(p.x); val py = viewport.pixelY(p.y)
        g.fill(Ellipse2D.Double(px - 2.5, py - 2.5, 5, 5))
        g.draw(Line2D.Double(px, py, px + n.x * normalPixels, py - n.y * normalPixels))

  private def drawGrid(g: Graphics2D, world: World, viewport: Viewport): Unit =
    world.detector match
      case grid: GridDetector if grid.gridSide * viewport.scale >= MinimumCellPixels =>
        val side = grid.gridSide
        val visible = viewport.visible
        g.setColor(GridColour)
        g.setStroke(BasicStroke(1f))
        var x = math.floor(visible.minX / side) * side
        while x <= visible.maxX do
          val px = viewport.pixelX(x)
          g.draw(Line2D.Double(px, 0, px, viewport.height))
          x += side
        var y = math.floor(visible.minY / side) * side
        while y <= visible.maxY do
          val py = viewport.pixelY(y)
          g.draw(Line2D.Double(0, py, viewport.width, py))
          y += side
      case _ => ()

  private def drawCaption(g: Graphics2D, caption: String): Unit =
    g.setFont(Font(Font.SANS_SERIF, Font.PLAIN, 13))
    g.setColor(JointColour)
    g.drawString(caption, 8, 18)
