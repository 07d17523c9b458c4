package sims.sweep

import java.nio.{ByteBuffer, ByteOrder}
import java.nio.charset.StandardCharsets
import org.scalatest.funsuite.AnyFunSuite

/** The file's layout, byte by byte where the format fixes it (that readers agree with it is
  * checked in SparkBackendSpec, which reads the files back with Spark's Parquet reader).
  */
class ParquetWriterSpec extends AnyFunSuite:
  private val columns = IndexedSeq(Column.Whole("run", IndexedSeq(0L, 1L, -3L)), Column.Real("x", IndexedSeq(0.5, -2.25, Double.NaN)))
  private val file = ParquetWriter.bytes(columns, 3)

  private def ascii(from: Int, until: Int) = String(file.slice(from, until), StandardCharsets.US_ASCII)
  private def littleEndian = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN)

  test("the file starts and ends with PAR1 and its last 8 bytes give the footer's length"):
    assert(ascii(0, 4) == "PAR1")
    assert(ascii(file.length - 4, file.length) == "PAR1")
    val footerLength = littleEndian.getInt(file.length - 8)
    assert(footerLength > 0 && footerLength < file.length - 12)
    // The footer names the columns and the writer.
    val footer = ascii(file.length - 8 - footerLength, file.length - 8)
    assert(footer.contains("schema") && footer.contains("run") && footer.contains("x") && footer.contains("sims-sweep"))

  test("each column's values are plain little-endian numbers after its page header"):
    // The first page's header starts right after the magic; its values follow it.
    val runValues = file.indexOfSlice(ByteBuffer.allocate(24).order(ByteOrder.LITTLE_ENDIAN).putLong(0).putLong(1).putLong(-3).array)
    assert(runValues > 4)
    val xValues = file.indexOfSlice(ByteBuffer.allocate(24).order(ByteOrder.LITTLE_ENDIAN)
        .putDouble(0.5).putDouble(-2.25).putDouble(Double.NaN).array)
    assert(xValues > runValues + 24)

  test("Thrift's compact protocol: deltas, zigzag varints, long field steps, lists and strings"):
    val writer = ThriftCompact()
    writer.structValue {
      writer.int32(1, -1) // delta 1, type 5; zigzag(-1) = 1
      writer.int64(3, 300) // delta 2, type 6; zigzag(300) = 600 = 0xd8 0x04
      writer.string(20, "ab") // delta 17 > 15: type 8 then the id as a zigzag varint (40)
      writer.int32List(21, Seq(1, 2))
    }
    assert(writer.bytes.map(_ & 0xff).toSeq ==
      Seq(0x15, 0x01, 0x26, 0xd8, 0x04, 0x08, 40, 2, 'a', 'b', 0x19, 0x25, 2, 4, 0))

  test("columns of different lengths are refused"):
    val error = intercept[IllegalArgumentException](ParquetWriter.bytes(columns, 4))
    assert(error.getMessage.contains("column run has 3 values, not 4"))
