package sims.sweep

import java.io.ByteArrayOutputStream
import java.nio.charset.StandardCharsets

/** The little of Apache Thrift's compact protocol that a Parquet file's headers and footer
  * need: structs of 32- and 64-bit integers, strings, structs and lists. Fields must be written
  * in the order of their ids, as the protocol encodes each id as the step from the one before.
  */
private[sweep] final class ThriftCompact:
  private val out = ByteArrayOutputStream()
  // The id of the last field written, of the struct being written and of those it is inside.
  private var lastField = 0
  private var outer = List.empty[Int]

  /** The bytes written so far. */
  def bytes: Array[Byte] = out.toByteArray

  /** An i32 field (also an enum's value). */
  def int32(id: Int, value: Int): Unit =
    field(id, ThriftCompact.Int32)
    varint(zigzag(value.toLong))

  /** An i64 field. */
  def int64(id: Int, value: Long): Unit =
    field(id, ThriftCompact.Int64)
    varint(zigzag(value))

  /** A string field. */
  def string(id: Int, value: String): Unit =
    field(id, ThriftCompact.Binary)
    stringValue(value)

  /** A struct field whose fields `body` writes. */
  def struct(id: Int)(body: => Unit): Unit =
    field(id, ThriftCompact.Struct)
    structValue(body)

  /** A list field of i32 values. */
  def int32List(id: Int, values: Seq[Int]): Unit =
    listHeader(id, ThriftCompact.Int32, values.size)
    values.foreach(v => varint(zigzag(v.toLong)))

  /** A list field of strings. */
  def stringList(id: Int, values: Seq[String]): Unit =
    listHeader(id, ThriftCompact.Binary, values.size)
    values.foreach(stringValue)

  /** A list field of structs, element `i`'s fields written by `element(i)`. */
  def structList(id: Int, size: Int)(element: Int => Unit): Unit =
    listHeader(id, ThriftCompact.Struct, size)
    for i <- 0 until size do structValue(element(i))

  /** A whole struct at the top level (a page header, the file's metadata). */
  def structValue(body: => Unit): Unit =
    outer = lastField :: outer
    lastField = 0
    body
    out.write(0) // the stop field
    lastField = outer.head
    outer = outer.tail

  private def field(id: Int, kind: Int): Unit =
    require(id > lastField, s"field $id written after field $lastField")
    val delta = id - lastField
    if delta <= 15 then out.write(delta << 4 | kind)
    else
      out.write(kind)
      varint(zigzag(id.toLong))
    lastField = id

  private def listHeader(id: Int, elementKind: Int, size: Int): Unit =
    field(id, ThriftCompact.List)
    if size < 15 then out.write(size << 4 | elementKind)
    else
      out.write(0xf0 | elementKind)
      varint(size.toLong)

  private def stringValue(value: String): Unit =
    val utf8 = value.getBytes(StandardCharsets.UTF_8)
    varint(utf8.length.toLong)
    out.write(utf8)

  private def zigzag(value: Long): Long = (value << 1) ^ (value >> 63)

  private def varint(value: Long): Unit =
    var rest = value
    while (rest & ~0x7fL) != 0 do
      out.write(((rest & 0x7f) | 0x80).toInt)
      rest >>>= 7
    out.write(rest.toInt)

/** The compact protocol's type codes. */
private[sweep] object ThriftCompact:
  val Int32 = 5
  val Int64 = 6
  val Binary = 8
  val List = 9
  val Struct = 12
