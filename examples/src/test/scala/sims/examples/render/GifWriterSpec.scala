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
    val scene = sims.scenes.BallStack
    val world = scene.build().world
    val picture = Renderer.image(world, Viewport.fit(scene.view, 120, 90), RenderOptions(smooth = false, caption = "x"))
    val gif = GifWriter(file, 40, Renderer.colours)
    gif.write(picture)
    gif.close()
    val back = ImageIO.read(file)
    for x <- 0 until 120; y <- 0 until 90 do assert(back.getRGB(x, y) == picture.getRGB(x, y), s"pixel ($x, $y)")

  test("with a palette, later frames store only what changed, and compose back to the pictures"):
    val file = Files.createTempFile("sims-gif", ".gif").toFile
    file.deleteOnExit()
    val scene = sims.scenes.Cannon
    val world = scene.build().world
    val viewport = Viewport.fit(scene.view, 160, 120)
    def picture() = Renderer.image(world, viewport, RenderOptions(smooth = false))
    val pictures = collection.mutable.ArrayBuffer(picture())
    val gif = GifWriter(file, 40, Renderer.colours)
    gif.write(pictures.last)
    for _ <- 1 to 3 do
      for _ <- 1 to 5 do world.step()
      pictures += picture()
      gif.write(pictures.last)
    gif.write(pictures.last) // nothing changed
    gif.close()
    val reader = ImageIO.getImageReadersByFormatName("gif").next()
    val input = ImageIO.createImageInputStream(file)
    try
      reader.setInput(input)
      assert(reader.getNumImages(true) == 5)
      val canvas = BufferedImage(160, 120, BufferedImage.TYPE_INT_RGB)
      val g = canvas.createGraphics()
      for k <- 0 until 5 do
        val tree = reader.getImageMetadata(k).getAsTree("javax_imageio_gif_image_1.0").asInstanceOf[IIOMetadataNode]
        val descriptor = tree.getElementsByTagName("ImageDescriptor").item(0).asInstanceOf[IIOMetadataNode]
        val left = descriptor.getAttribute("imageLeftPosition").toInt
        val top = descriptor.getAttribute("imageTopPosition").toInt
        val part = reader.read(k)
        if k > 0 then assert(part.getWidth * part.getHeight < 160 * 120, s"frame $k stores only a part")
        g.drawImage(part, left, top, null)
        val expected = pictures(math.min(k, 3))
        for x <- 0 until 160; y <- 0 until 120 do
          assert(canvas.getRGB(x, y) == expected.getRGB(x, y), s"frame $k pixel ($x, $y)")
      g.dispose()
    finally
      input.close()
      reader.dispose()
