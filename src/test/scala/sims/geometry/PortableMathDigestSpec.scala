package sims.geometry

import org.scalatest.funsuite.AnyFunSuite

/** PortableMath's results over 200,000 arguments of each function, folded into one fingerprint
  * per function: the fingerprints of `java.lang.StrictMath`'s results on the JVM (which
  * PortableMathSpec checks there), and this test finds the same ones wherever it runs — on the
  * JVM and on Node.
  */
class PortableMathDigestSpec extends AnyFunSuite:
  import PortableMathDigestSpec.*

  test("sin, cos, atan2, acos and hypot give StrictMath's fingerprints on this platform"):
    assert(digests(PortableMath.sin, PortableMath.cos, PortableMath.atan2, PortableMath.acos, PortableMath.hypot) == Expected)

object PortableMathDigestSpec:
  /** Of sin, cos, atan2, acos and hypot, computed from StrictMath's results on the JVM. */
  val Expected: Seq[String] =
    Seq("f74b43213d12ac35", "0e20fdaaaa52776d", "d0b600186ae60678", "eb1ca0225c339020", "eed79d19ba232107")

  val Count = 200_000

  /** A fixed stream of 64-bit values (xorshift64*), the same on every platform. */
  final class Bits(seed: Long):
    private var state = seed
    def next(): Long =
      state ^= state >>> 12
      state ^= state << 25
      state ^= state >>> 27
      state * 0x2545f4914f6cdd1dL
    /** A double in [0, 1). */
    def unit(): Double = (next() >>> 11).toDouble / (1L << 53).toDouble

  /** Arguments of every kind: any bit pattern, unit scale, medium, huge, tiny, next to n pi/2. */
  def argument(bits: Bits): Double =
    val x = (bits.next() & 7).toInt match
      case 0 | 1 => java.lang.Double.longBitsToDouble(bits.next())
      case 2 => bits.unit() * 4
      case 3 => bits.unit() * 1e6
      case 4 => bits.unit() * math.pow(2, (bits.next() & 1023).toInt)
      case 5 => bits.unit() * math.pow(2, -(bits.next() & 1023).toInt)
      case _ =>
        val near = (1 + (bits.next() & 0xfffff)).toDouble * (math.Pi / 2)
        near + ((bits.next() & 15) - 8).toDouble * math.ulp(near)
    if (bits.next() & 1) == 0 then x else -x

  private def fold(h: Long, value: Double): Long = (h ^ java.lang.Double.doubleToLongBits(value)) * 0x100000001b3L

  private def hex(h: Long): String =
    val digits = java.lang.Long.toHexString(h)
    "0" * (16 - digits.length) + digits

  /** The fingerprints of these five functions' results. */
  def digests(sin: Double => Double, cos: Double => Double, atan2: (Double, Double) => Double,
      acos: Double => Double, hypot: (Double, Double) => Double): Seq[String] =
    def one(f: Bits => Double, seed: Long): String =
      val bits = Bits(seed)
      var h = 0xcbf29ce484222325L
      var k = 0
      while k < Count do
        h = fold(h, f(bits))
        k += 1
      hex(h)
    Seq(
      one(b => sin(argument(b)), 11),
      one(b => cos(argument(b)), 12),
      one(b => atan2(argument(b), argument(b)), 13),
      one(b => acos(if (b.next() & 1) == 0 then argument(b) else 2 * b.unit() - 1), 14),
      one(b => hypot(argument(b), argument(b)), 15))
