package sims.examples.render

import java.awt.image.BufferedImage
import java.io.File
import javax.imageio.{IIOImage, ImageIO, ImageTypeSpecifier}
import javax.imageio.metadata.{IIOMetadata, IIOMetadataNode}
import javax.imageio.stream.ImageOutputStream

/** Writes an animated, looping GIF frame by frame with the JDK's GIF writer.
  *
  * @param file             the file to write (replaced)
  * @param frameDelayMillis time each frame is shown; GIF stores hundredths of a second
  */
final class GifWriter(file: File, frameDelayMillis: Int) extends AutoCloseable:
  private val writer =
    val writers = ImageIO.getImageWritersByFormatName("gif")
    if !writers.hasNext then throw IllegalStateException("this JDK has no GIF writer")
    writers.next()
  if file.exists() then file.delete()
  private val output: ImageOutputStream = ImageIO.createImageOutputStream(file)
  writer.setOutput(output)
  writer.prepareWriteSequence(null)
  private var count = 0

  /** Number of frames written so far. */
  def frames: Int = count

  /** Appends one frame. */
  def write(frame: BufferedImage): Unit =
    val metadata = frameMetadata(frame)
    writer.writeToSequence(IIOImage(frame, null, metadata), null)
    count += 1

  /** Finishes the file. */
  def close(): Unit =
    try
      writer.endWriteSequence()
    finally
      output.close()
      writer.dispose()

  /** Metadata of one frame: its delay and, on the first frame, the loop-forever extension. */
  private def frameMetadata(frame: BufferedImage): IIOMetadata =
    val metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(frame), null)
    val format = metadata.getNativeMetadataFormatName
    val root = metadata.getAsTree(format).asInstanceOf[IIOMetadataNode]
    val control = child(root, "GraphicControlExtension")
    control.setAttribute("disposalMethod", "none")
    control.setAttribute("userInputFlag", "FALSE")
    control.setAttribute("transparentColorFlag", "FALSE")
    control.setAttribute("delayTime", math.max(1, math.round(frameDelayMillis / 10.0).toInt).toString)
    control.setAttribute("transparentColorIndex", "0")
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
  private def child(parent: IIOMetadataNode, name: String): IIOMetadataNode =
    (0 until parent.getLength).map(parent.item).collectFirst {
      case node: IIOMetadataNode if node.getNodeName == name => node
    }.getOrElse {
      val node = IIOMetadataNode(name)
      parent.appendChild(node)
      node
    }
