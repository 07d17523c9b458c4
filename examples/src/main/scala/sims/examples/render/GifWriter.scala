package sims.examples.render

import java.awt.Color
import java.awt.image.{BufferedImage, DataBuffer, IndexColorModel}
import scala.collection.mutable
import java.io.File
import javax.imageio.{IIOImage, ImageIO, ImageTypeSpecifier}
import javax.imageio.metadata.{IIOMetadata, IIOMetadataNode}
import javax.imageio.stream.ImageOutputStream

/** Writes an animated, looping GIF frame by frame with the JDK's GIF writer.
  *
  * @param file             the file to write (replaced)
  * @param frameDelayMillis time each frame is shown; GIF stores hundredths of a second
  * @param palette          if not empty (at most 256 colours), every pixel is stored as the
  *                         nearest of these colours: pictures drawn in exactly these colours
  *                         stay exact and compress far better than the JDK's own per-frame
  *                         colour reduction; then each frame after the first stores only
  *                         the rectangle where it differs from the one before
  */
final class GifWriter(file: File, frameDelayMillis: Int, palette: Seq[Color] = Nil) extends AutoCloseable:
  require(palette.size <= 256, s"a GIF palette has at most 256 colours, got ${palette.size}")
  private val writer =
    val writers = ImageIO.getImageWritersByFormatName("gif")
    if !writers.hasNext then throw IllegalStateException("this JDK has no GIF writer")
    writers.next()
  if file.exists() then file.delete()
  private val output: ImageOutputStream = ImageIO.createImageOutputStream(file)
  writer.setOutput(output)
  writer.prepareWriteSequence(null)
  private var count = 0
  private var previous: BufferedImage = null

  /** Number of frames written so far. */
  def frames: Int = count

  /** Appends one frame. */
  def write(frame: BufferedImage): Unit =
    if palette.isEmpty then writer.writeToSequence(IIOImage(frame, null, frameMetadata(frame, 0, 0)), null)
    else
      val current = indexed(frame)
      val (left, top, width, height) = changedRectangle(previous, current)
      val stored = if previous == null then current else current.getSubimage(left, top, width, height)
      writer.writeToSequence(IIOImage(stored, null, frameMetadata(stored, left, top)), null)
      previous = current
    count += 1

  /** The smallest rectangle (left, top, width, height) holding every pixel that differs
    * between the two frames; the whole frame when there is no previous one or a different
    * size, a single pixel when nothing changed (a frame must still be written for its delay).
    */
  private def changedRectangle(before: BufferedImage, after: BufferedImage): (Int, Int, Int, Int) =
    if before == null || before.getWidth != after.getWidth || before.getHeight != after.getHeight then
      (0, 0, after.getWidth, after.getHeight)
    else
      val a = before.getRaster.getDataBuffer.asInstanceOf[java.awt.image.DataBufferByte].getData
      val b = after.getRaster.getDataBuffer.asInstanceOf[java.awt.image.DataBufferByte].getData
      val width = after.getWidth
      var minX = Int.MaxValue; var minY = Int.MaxValue; var maxX = -1; var maxY = -1
      var i = 0
      while i < b.length do
        if a(i) != b(i) then
          val x = i % width
          val y = i / width
          if x < minX then minX = x
          if x > maxX then maxX = x
          if y < minY then minY = y
          if y > maxY then maxY = y
        i += 1
      if maxX < 0 then (0, 0, 1, 1) else (minX, minY, maxX - minX + 1, maxY - minY + 1)

  /** Finishes the file. */
  def close(): Unit =
    try
      writer.endWriteSequence()
    finally
      output.close()
      writer.dispose()

  private lazy val colourModel: IndexColorModel =
    // GIF colour tables have a power-of-two size; unused entries repeat the first colour.
    val size = Iterator.iterate(2)(_ * 2).find(_ >= palette.size).get
    val rgb = Array.tabulate(size)(i => palette(if i < palette.size then i else 0).getRGB)
    IndexColorModel(8, size, rgb, 0, false, -1, DataBuffer.TYPE_BYTE)
  private val nearestOf = mutable.HashMap.empty[Int, Byte]

  /** The frame with every pixel replaced by the index of the nearest palette colour. */
  private def indexed(frame: BufferedImage): BufferedImage =
    val result = BufferedImage(frame.getWidth, frame.getHeight, BufferedImage.TYPE_BYTE_INDEXED, colourModel)
    val raster = result.getRaster
    val row = new Array[Int](frame.getWidth)
    val indices = new Array[Int](frame.getWidth)
    for y <- 0 until frame.getHeight do
      frame.getRGB(0, y, frame.getWidth, 1, row, 0, frame.getWidth)
      for x <- row.indices do indices(x) = nearestOf.getOrElseUpdate(row(x) & 0xffffff, nearest(row(x))) & 0xff
      raster.setPixels(0, y, frame.getWidth, 1, indices)
    result

  private def nearest(rgb: Int): Byte =
    def distance(c: Color): Int =
      val dr = c.getRed - ((rgb >> 16) & 0xff)
      val dg = c.getGreen - ((rgb >> 8) & 0xff)
      val db = c.getBlue - (rgb & 0xff)
      dr * dr + dg * dg + db * db
    palette.indices.minBy(i => distance(palette(i))).toByte

  /** Metadata of one frame placed at (left, top): its delay, its colour table and, on the
    * first frame, the loop-forever extension.
    */
  private def frameMetadata(frame: BufferedImage, left: Int, top: Int): IIOMetadata =
    val metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(frame), null)
    val format = metadata.getNativeMetadataFormatName
    val root = metadata.getAsTree(format).asInstanceOf[IIOMetadataNode]
    val control = child(root, "GraphicControlExtension")
    // Each frame is drawn over the last one: the unchanged parts stay on screen.
    control.setAttribute("disposalMethod", "doNotDispose")
    val descriptor = child(root, "ImageDescriptor")
    descriptor.setAttribute("imageLeftPosition", left.toString)
    descriptor.setAttribute("imageTopPosition", top.toString)
    descriptor.setAttribute("imageWidth", frame.getWidth.toString)
    descriptor.setAttribute("imageHeight", frame.getHeight.toString)
    control.setAttribute("userInputFlag", "FALSE")
    control.setAttribute("transparentColorFlag", "FALSE")
    control.setAttribute("delayTime", math.max(1, math.round(frameDelayMillis / 10.0).toInt).toString)
    control.setAttribute("transparentColorIndex", "0")
    frame.getColorModel match
      case model: IndexColorModel =>
        // The writer does not take the colour table from the image by itself: state it.
        val table = child(root, "LocalColorTable")
        table.setAttribute("sizeOfLocalColorTable", model.getMapSize.toString)
        table.setAttribute("sortFlag", "FALSE")
        while table.getLength > 0 do table.removeChild(table.getFirstChild)
        for i <- 0 until model.getMapSize do
          val entry = IIOMetadataNode("ColorTableEntry")
          entry.setAttribute("index", i.toString)
          entry.setAttribute("red", model.getRed(i).toString)
          entry.setAttribute("green", model.getGreen(i).toString)
          entry.setAttribute("blue", model.getBlue(i).toString)
          table.appendChild(entry)
      case _ => ()
    if count == 0 then
      val extensions = child(root, "ApplicationExtensions")
      val loop = IIOMetadataNode("ApplicationExtension")
      loop.setAttribute("applicationID", "NETSCAPE")
      loop.setAttribute("authenticationCode", "2.0")
      // Sub-block 1 with loop count 0: repeat forever.
      loop.setUserObject(Array[Byte](1, 0, 0))
      extensions.appendChild(loop)
    metadata.setFromTree(format, root)
    metadata

  /** The child of `parent` with this name, created if missing. */
  private def child(parent: IIOMetadataNode, name: String): IIOMetadataNode = (0 until parent.getLength).map(parent.item).collectFirst {
    case node: IIOMetadataNode if node.getNodeName == name => node
  }.getOrElse {
    val node = IIOMetadataNode(name)
    parent.appendChild(node)
    node
  }
