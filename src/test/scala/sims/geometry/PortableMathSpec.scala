package sims.geometry

import org.scalatest.funsuite.AnyFunSuite

/** PortableMath against the JVM's `java.lang.StrictMath` (fdlibm), bit for bit, over millions
  * of arguments with the hard ranges of each function (JVM only: StrictMath has no Scala.js
  * counterpart; PortableMathDigestSpec carries the result over to Node).
  */
class PortableMathSpec extends AnyFunSuite:
  import PortableMathSpec.*

  private def sameBits(a: Double, b: Double): Boolean =
    java.lang.Double.doubleToLongBits(a) == java.lang.Double.doubleToLongBits(b)

  /** Compares `ours` with `strict` at every argument; reports the first few differences. */
  private def check1(name: String, args: Iterator[Double], ours: Double => Double,
      strict: Double => Double): Int =
    var count = 0
    val wrong = List.newBuilder[String]
    var wrongCount = 0
    for x <- args do
      count += 1
      val (o, s) = (ours(x), strict(x))
      if !sameBits(o, s) then
        wrongCount += 1
        if wrongCount <= 5 then wrong += s"$name($x) = $o, StrictMath: $s"
    assert(wrongCount == 0, s"$wrongCount of $count differ: ${wrong.result().mkString("; ")}")
    count

  private def check2(name: String, args: Iterator[(Double, Double)], ours: (Double, Double) => Double,
      strict: (Double, Double) => Double): Int =
    var count = 0
    val wrong = List.newBuilder[String]
    var wrongCount = 0
    for (x, y) <- args do
      count += 1
      val (o, s) = (ours(x, y), strict(x, y))
      if !sameBits(o, s) then
        wrongCount += 1
        if wrongCount <= 5 then wrong += s"$name($x, $y) = $o, StrictMath: $s"
    assert(wrongCount == 0, s"$wrongCount of $count differ: ${wrong.result().mkString("; ")}")
    count

  test("sin and cos equal StrictMath's on 5 million arguments: small, medium, near multiples of pi/2, huge"):
    for (name, ours, strict) <- Seq[(String, Double => Double, Double => Double)](
        ("sin", PortableMath.sin, StrictMath.sin), ("cos", PortableMath.cos, StrictMath.cos)) do
      val count = check1(name, angleArguments(seed = 1), ours, strict)
      assert(count >= 5_000_000)

  test("atan2 equals StrictMath's on 3 million pairs, with zeros, infinities and NaN in every quadrant"):
    val count = check2("atan2", pairArguments(seed = 2), PortableMath.atan2, StrictMath.atan2)
    assert(count >= 3_000_000)

  test("atan equals StrictMath's on 2 million arguments around each breakpoint"):
    val random = java.util.SplittableRandom(3)
    val breakpoints = Seq(0.0, 7.0 / 16, 11.0 / 16, 19.0 / 16, 39.0 / 16, 1e20, math.pow(2, 66), 1e-9)
    val args = Iterator.fill(2_000_000) {
      val b = breakpoints(random.nextInt(breakpoints.size))
      val x = if random.nextBoolean() then b * (1 + (random.nextDouble() - 0.5) * 0.1) else randomBits(random)
      if random.nextBoolean() then x else -x
    } ++ specials.iterator
    check1("atan", args, PortableMath.atan, StrictMath.atan)

  test("acos equals StrictMath's on 3 million arguments in [-1, 1], next to +-1, +-1/2 and 0, and outside"):
    val random = java.util.SplittableRandom(4)
    val args = Iterator.fill(3_000_000) {
      random.nextInt(6) match
        case 0 => random.nextDouble() * 2 - 1
        case 1 => 1 - random.nextDouble() * math.pow(2, -random.nextInt(60))
        case 2 => -1 + random.nextDouble() * math.pow(2, -random.nextInt(60))
        case 3 => (if random.nextBoolean() then 0.5 else -0.5) + (random.nextDouble() - 0.5) * 1e-3
        case 4 => (random.nextDouble() - 0.5) * math.pow(2, -random.nextInt(1080))
        case _ => randomBits(random)
    } ++ specials.iterator ++ Iterator(math.nextUp(1.0), math.nextDown(-1.0), math.nextDown(1.0))
    check1("acos", args, PortableMath.acos, StrictMath.acos)

  test("hypot equals StrictMath's on 3 million pairs, with huge, tiny and subnormal sides"):
    val count = check2("hypot", pairArguments(seed = 5), PortableMath.hypot, StrictMath.hypot)
    assert(count >= 3_000_000)

  test("StrictMath's results give the fingerprints that PortableMathDigestSpec expects on every platform"):
    assert(PortableMathDigestSpec.digests(StrictMath.sin, StrictMath.cos, StrictMath.atan2, StrictMath.acos,
      StrictMath.hypot) == PortableMathDigestSpec.Expected)

  test("the tables of 2/pi and pi/2 hold those numbers' binary digits (checked with big integers)"):
    // pi * 2^bits by Machin's formula, in exact integer arithmetic.
    val bits = 1800
    def arctanOfInverse(n: Int): BigInt =
      val one = BigInt(1) << bits
      var term = one / n
      var sum = term
      var k = 1
      while term != 0 do
        term /= BigInt(n) * n
        sum += (if k % 2 == 1 then -(term / (2 * k + 1)) else term / (2 * k + 1))
        k += 1
      sum
    val pi = arctanOfInverse(5) * 16 - arctanOfInverse(239) * 4
    val twoOverPi = (BigInt(1) << (2 * bits + 1)) / pi
    for (chunk, k) <- AngleReduction.TwoOverPiChunks.zipWithIndex do
      assert(chunk == ((twoOverPi >> (bits - 24 * (k + 1))) & 0xffffff).toInt, s"chunk $k")
    var rest = pi / 2
    for (chunk, k) <- AngleReduction.PiOver2Chunks.zipWithIndex do
      val shift = bits - (23 + 24 * k)
      val digits = rest >> shift
      assert(chunk == digits.toDouble * math.pow(2, -(23 + 24 * k)), s"piece $k")
      rest -= digits << shift

object PortableMathSpec:
  /** Signed zeros, infinities, NaN, the extremes and the subnormal edge. */
  val specials: Seq[Double] = Seq(0.0, -0.0, Double.PositiveInfinity, Double.NegativeInfinity, Double.NaN,
    Double.MaxValue, -Double.MaxValue, Double.MinPositiveValue, -Double.MinPositiveValue,
    java.lang.Double.MIN_NORMAL, -java.lang.Double.MIN_NORMAL, 1.0, -1.0, 0.5, -0.5, math.Pi, -math.Pi,
    math.Pi / 2, -math.Pi / 2, math.Pi / 4, -math.Pi / 4)

  /** Any double, every exponent alike: NaNs, subnormals and infinities included. */
  def randomBits(random: java.util.SplittableRandom): Double = java.lang.Double.longBitsToDouble(random.nextLong())

  /** 5 million angles: uniform small and medium ones, ones right next to multiples of pi/2
    * (where the reduction cancels most bits), the medium/huge boundary near 2^19 pi/2, huge ones
    * of every exponent, subnormals, and the specials.
    */
  def angleArguments(seed: Long): Iterator[Double] =
    val random = java.util.SplittableRandom(seed)
    Iterator.fill(5_000_000) {
      val x = random.nextInt(8) match
        case 0 => random.nextDouble() * 4
        case 1 => random.nextDouble() * 100
        case 2 => random.nextDouble() * 1e6
        case 3 => // next to n pi/2, a few ulps away or much closer
          val n = 1 + random.nextInt(1 << 20)
          val near = n * (math.Pi / 2)
          near + (random.nextInt(21) - 10) * math.ulp(near) * (if random.nextBoolean() then 1 else 1e-3)
        case 4 => 823549.6 * (1 + (random.nextDouble() - 0.5) * 1e-3) // around 2^19 pi/2
        case 5 => random.nextDouble() * math.pow(2, random.nextInt(1024)) // huge, any exponent
        case 6 => random.nextDouble() * math.pow(2, -random.nextInt(1075)) // tiny and subnormal
        case _ => randomBits(random)
      if random.nextBoolean() then x else -x
    } ++ specials.iterator

  /** 3 million pairs: both sides of random exponents (near each other or far apart), unit
    * scale, the specials crossed with each other and with random values.
    */
  def pairArguments(seed: Long): Iterator[(Double, Double)] =
    val random = java.util.SplittableRandom(seed)
    def signed(x: Double) = if random.nextBoolean() then x else -x
    val crossed = for a <- specials.iterator; b <- specials.iterator yield (a, b)
    Iterator.fill(3_000_000) {
      random.nextInt(5) match
        case 0 => (signed(random.nextDouble() * 10), signed(random.nextDouble() * 10))
        case 1 =>
          val e = random.nextInt(2100) - 1075
          (signed(random.nextDouble() * math.pow(2, e)), signed(random.nextDouble() * math.pow(2, e + random.nextInt(9) - 4)))
        case 2 =>
          (signed(random.nextDouble() * math.pow(2, random.nextInt(2100) - 1075)),
            signed(random.nextDouble() * math.pow(2, random.nextInt(2100) - 1075)))
        case 3 =>
          val s = specials(random.nextInt(specials.size))
          if random.nextBoolean() then (s, signed(random.nextDouble())) else (signed(random.nextDouble()), s)
        case _ => (randomBits(random), randomBits(random))
    } ++ crossed

/** Records PortableMathDigestSpec's fingerprints from StrictMath (run with `Test/runMain`). */
@main def recordPortableMathDigests(): Unit =
  println(PortableMathDigestSpec.digests(StrictMath.sin, StrictMath.cos, StrictMath.atan2, StrictMath.acos,
      StrictMath.hypot).map(d => s"\"$d\"").mkString("Seq(", ", ", ")"))
