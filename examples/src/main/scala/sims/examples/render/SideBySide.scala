package sims.examples.render

import java.awt.BasicStroke
import java.awt.geom.Line2D
import java.awt.image.BufferedImage
import sims.dynamics.World

/** Two worlds drawn next to each other through the same [[Viewport]], each with its caption,
  * split by a line: the pictures of a comparison of two solvers on one scene.
  */
object SideBySide:
  /** A picture twice the viewport's width: `left` on the left, `right` on the right. */
  def image(left: World, right: World, viewport: Viewport, leftCaption: String, rightCaption: String,
      smooth: Boolean = true): BufferedImage =
    val picture = BufferedImage(2 * viewport.width, viewport.height, BufferedImage.TYPE_INT_RGB)
    val g = picture.createGraphics()
    try
      for (world, caption, offset) <- Seq((left, leftCaption, 0), (right, rightCaption, viewport.width)) do
        val half = g.create(offset, 0, viewport.width, viewport.height).asInstanceOf[java.awt.Graphics2D]
        try Renderer.draw(half, world, viewport, RenderOptions(caption = caption, smooth = smooth))
        finally half.dispose()
      g.setColor(Renderer.JointColour)
      g.setStroke(BasicStroke(2f))
      g.draw(Line2D.Double(viewport.width, 0, viewport.width, viewport.height))
    finally g.dispose()
    picture
