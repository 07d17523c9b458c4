package sims.sweep

import java.io.ByteArrayOutputStream
import java.nio.{ByteBuffer, ByteOrder}
import java.nio.charset.StandardCharsets

/** Writes a table as an Apache Parquet file without any library: a few hundred runs' or a few
  * million's worth of numbers need only the format's simplest form, which every Parquet reader
  * reads. The file holds one row group; each column is one data page of plain little-endian
  * values (INT64 or DOUBLE, required, so no repetition or definition levels), uncompressed; the
  * page headers and the footer are Thrift compact structs (the format's parquet.thrift).
  *
  * parquet-hadoop would do the same through Hadoop's file system classes, dozens of jars
  * (Hadoop's client alone is tens of megabytes) for what is here a hundred lines; a sweep's
  * local back end stays free of them and of Spark.
  */
private[sweep] object ParquetWriter:
  private val Magic = "PAR1".getBytes(StandardCharsets.US_ASCII)

  // Values of parquet.thrift's enums.
  private val TypeInt64 = 2
  private val TypeDouble = 5
  private val Required = 0
  private val Plain = 0
  private val Rle = 3
  private val Uncompressed = 0
  private val DataPage = 0

  /** The file's bytes for `columns`, each with `rows` values. */
  def bytes(columns: IndexedSeq[Column], rows: Int): Array[Byte] =
    columns.foreach(c => require(c.size == rows, s"column ${c.name} has ${c.size} values, not $rows"))
    require(rows.toLong * 8 <= Int.MaxValue, s"a column's page holds at most ${Int.MaxValue / 8} values, got $rows")
    val file = ByteArrayOutputStream()
    file.write(Magic)
    final case class Chunk(offset: Long, size: Long)
    val chunks = columns.map { column =>
      val offset = file.size.toLong
      val values = plain(column)
      val header = ThriftCompact()
      header.structValue {
        header.int32(1, DataPage)
        header.int32(2, values.length)
        header.int32(3, values.length)
        header.struct(5) {
          header.int32(1, rows)
          header.int32(2, Plain)
          header.int32(3, Rle)
          header.int32(4, Rle)
        }
      }
      file.write(header.bytes)
      file.write(values)
      Chunk(offset, file.size - offset)
    }
    val footer = ThriftCompact()
    footer.structValue {
      footer.int32(1, 1) // format version
      footer.structList(2, columns.size + 1) { i =>
        if i == 0 then
          footer.string(4, "schema")
          footer.int32(5, columns.size)
        else
          footer.int32(1, kind(columns(i - 1)))
          footer.int32(3, Required)
          footer.string(4, columns(i - 1).name)
      }
      footer.int64(3, rows)
      // No row group in a file without rows (readers expect none rather than an empty one).
      footer.structList(4, if rows == 0 then 0 else 1) { _ =>
        footer.structList(1, columns.size) { i =>
          footer.int64(2, chunks(i).offset)
          footer.struct(3) {
            footer.int32(1, kind(columns(i)))
            footer.int32List(2, Seq(Plain))
            footer.stringList(3, Seq(columns(i).name))
            footer.int32(4, Uncompressed)
            footer.int64(5, rows)
            footer.int64(6, chunks(i).size)
            footer.int64(7, chunks(i).size)
            footer.int64(9, chunks(i).offset)
          }
        }
        footer.int64(2, chunks.map(_.size).sum)
        footer.int64(3, rows)
      }
      footer.string(6, "sims-sweep")
    }
    val metadata = footer.bytes
    file.write(metadata)
    file.write(ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN).putInt(metadata.length).array)
    file.write(Magic)
    file.toByteArray

  private def kind(column: Column): Int = column match
    case _: Column.Whole => TypeInt64
    case _: Column.Real => TypeDouble

  private def plain(column: Column): Array[Byte] =
    val buffer = ByteBuffer.allocate(column.size * 8).order(ByteOrder.LITTLE_ENDIAN)
    column match
      case Column.Whole(_, values) => values.foreach(buffer.putLong)
      case Column.Real(_, values) => values.foreach(buffer.putDouble)
    buffer.array
