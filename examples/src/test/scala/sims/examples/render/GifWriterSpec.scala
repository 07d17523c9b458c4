package sims.examples.render

import java.awt.Color
import java.awt.image.BufferedImage
import java.nio.file.Files
import javax.imageio.ImageIO
import javax.imageio.metadata.IIOMetadataNode
import org.scalatest.funsuite.AnyFunSuite

/** The animated GIF: frame count, delay and looping, read back with ImageIO. */
class GifWriterSpec extends AnyFunSuite:
  test("frames, their delay and the loop extension are written"):
    val file = Files.createTempFile("sims-gif", ".gif").toFile
    file.deleteOnExit()
    val gif = GifWriter(file, 40)
    for colour <- Seq(Color.RED, Color.GREEN, Color.BLUE) do
      val frame = BufferedImage(32, 24, BufferedImage.TYPE_INT_RGB)
      val g = frame.createGraphics()
      g.setColor(colour)
      g.fillRect(0, 0, 32, 24)
      g.dispose()
      gif.write(frame)
    gif.close()
    assert(gif.frames == 3)
    val reader = ImageIO.getImageReadersByFormatName("gif").next()
    val input = ImageIO.createImageInputStream(file)
    try
      reader.setInput(input)
      assert(reader.getNumImages(true) == 3)
      val first = reader.read(0)
      assert(first.getWidth == 32 && first.getHeight == 24)
      assert(Color(first.getRGB(5, 5)) == Color.RED)
      assert(Color(reader.read(2).getRGB(5, 5)) == Color.BLUE)
      val tree = reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0").asInstanceOf[IIOMetadataNode]
      val control = tree.getElementsByTagName("GraphicControlExtension").item(0).asInstanceOf[IIOMetadataNode]
      assert(control.getAttribute("delayTime") == "4")
      val loop = tree.getElementsByTagName("ApplicationExtension").item(0).asInstanceOf[IIOMetadataNode]
      assert(loop.getAttribute("applicationID") == "NETSCAPE")
    finally
      input.close()
      reader.dispose()

  test("with a palette, the renderer's unsmoothed pictures are stored exactly"):
    val file = Files.createTempFile("sims-gif", ".gif").toFile
    file.deleteOnExit()
    val scene = sims.examples.scenes.BallStack
    val world = scene.build().world
    val picture = Renderer.image(world, Viewport.fit(scene.view, 120, 90), RenderOptions(smooth = false, caption = "x"))
    val gif = GifWriter(file, 40, Renderer.colours)
    gif.write(picture)
    gif.close()
    val back = ImageIO.read(file)
    for x <- 0 until 120; y <- 0 until 90 do assert(back.getRGB(x, y) == picture.getRGB(x, y), s"pixel ($x, $y)")
