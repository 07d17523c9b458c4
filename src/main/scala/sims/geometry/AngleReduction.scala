package sims.geometry

import PortableMath.{fromWords, highWord, lowWord}

/** Reduction of an angle to the range [-pi/4, pi/4] for [[PortableMath]]'s sine and cosine:
  * `x = n * pi/2 + (head + tail)`, with `head + tail` carrying about 100 correct bits, so the
  * sine and cosine of huge arguments are still correctly related to the real number `x`.
  *
  * Two methods, as in fdlibm: for |x| up to about 2^19 * pi/2, `n * pi/2` is subtracted in up to
  * three pieces of pi/2 (each exact in fewer than 53 bits, so every product `n * piece` is
  * exact); beyond that, the bits of 2/pi that matter for `x` are multiplied out in 24-bit
  * chunks (the Payne-Hanek method), where `x`'s exponent picks the chunks.
  */
private[geometry] object AngleReduction:
  // pi/2 cut into three 33-bit pieces, each followed by what is left after it.
  private val PiOver2Piece1 = 1.57079632673412561417e+00
  private val PiOver2Rest1 = 6.07710050650619224932e-11
  private val PiOver2Piece2 = 6.07710050630396597660e-11
  private val PiOver2Rest2 = 2.02226624879595063154e-21
  private val PiOver2Piece3 = 2.02226624871116645580e-21
  private val PiOver2Rest3 = 8.47842766036889956997e-32
  private val TwoOverPi = 6.36619772367581382433e-01
  private val TwoTo24 = 16777216.0
  private val TwoToMinus24 = 1.0 / TwoTo24

  /** High words of n * pi/2 for n = 1 to 32: where x is this close to a multiple of pi/2, the
    * first piece cancels too many bits, and the reduction takes its further pieces.
    */
  private val multipleHighWords: Array[Int] =
    Array.tabulate(32)(k => highWord((k + 1) * (math.Pi / 2)))

  /** The binary digits of 2/pi after the point, 24 at a time (1584 bits: enough for any double). */
  private[geometry] val TwoOverPiChunks: Array[Int] = Array(
    0xa2f983, 0x6e4e44, 0x1529fc, 0x2757d1, 0xf534dd, 0xc0db62, 0x95993c, 0x439041, 0xfe5163,
    0xabdebb, 0xc561b7, 0x246e3a, 0x424dd2, 0xe00649, 0x2eea09, 0xd1921c, 0xfe1deb, 0x1cb129,
    0xa73ee8, 0x8235f5, 0x2ebb44, 0x84e99c, 0x7026b4, 0x5f7e41, 0x3991d6, 0x398353, 0x39f49c,
    0x845f8b, 0xbdf928, 0x3b1ff8, 0x97ffde, 0x05980f, 0xef2f11, 0x8b5a0a, 0x6d1f6d, 0x367ecf,
    0x27cb09, 0xb74f46, 0x3f669e, 0x5fea2d, 0x7527ba, 0xc7ebe5, 0xf17b3d, 0x0739f7, 0x8a5292,
    0xea6bfb, 0x5fb11f, 0x8d5d08, 0x560330, 0x46fc7b, 0x6babf0, 0xcfbc20, 0x9af436, 0x1da9e3,
    0x91615e, 0xe61b08, 0x659985, 0x5f14a0, 0x68408d, 0xffd880, 0x4d7327, 0x310606, 0x1556ca,
    0x73a8c9, 0x60e27b, 0xc08c6b)

  /** pi/2 as a sum of eight doubles of 24 bits each. */
  private[geometry] val PiOver2Chunks: Array[Double] = Array(
    1.57079625129699707031e+00, 7.54978941586159635335e-08, 5.39030252995776476554e-15,
    3.28200341580791294123e-22, 1.27065575308067607349e-29, 1.22933308981111328932e-36,
    2.73370053816464559624e-44, 2.16741683877804819444e-51)

  /** The sine (`quarterTurns` 0) or cosine (`quarterTurns` 1) of a finite or infinite `x` with
    * |x| > pi/4 (high word of |x| at least 0x3fe921fc), from the reduced angle; in the
    * common ranges without allocating.
    */
  def sineOf(x: Double, quarterTurns: Int): Double =
    val hx = highWord(x)
    val ix = hx & 0x7fffffff
    if ix < 0x4002d97c then sineNearPiOver2(x, hx, ix, quarterTurns)
    else if ix <= 0x413921fb then sineMedium(x, hx, ix, quarterTurns)
    else
      val out = new Array[Double](2)
      val n = reduceLarge(x, hx, ix, out)
      PortableMath.sineOfReduced(n + quarterTurns, out(0), out(1))

  /** |x| < 3pi/4: n is +-1, one or two pieces of pi/2 suffice. */
  private def sineNearPiOver2(x: Double, hx: Int, ix: Int, quarterTurns: Int): Double =
    // Next to pi/2 itself the first piece cancels 33 bits: take the second piece too.
    val nearPiOver2 = ix == 0x3ff921fb
    if hx > 0 then
      var z = x - PiOver2Piece1
      val rest = if nearPiOver2 then
        z -= PiOver2Piece2
        PiOver2Rest2
      else PiOver2Rest1
      val head = z - rest
      PortableMath.sineOfReduced(1 + quarterTurns, head, (z - head) - rest)
    else
      var z = x + PiOver2Piece1
      val rest = if nearPiOver2 then
        z += PiOver2Piece2
        PiOver2Rest2
      else PiOver2Rest1
      val head = z + rest
      PortableMath.sineOfReduced(-1 + quarterTurns, head, (z - head) + rest)

  /** |x| up to about 2^19 * pi/2: n * pi/2 taken off in one to three pieces. */
  private def sineMedium(x: Double, hx: Int, ix: Int, quarterTurns: Int): Double =
    val t0 = math.abs(x)
    val n = (t0 * TwoOverPi + 0.5).toInt
    val multiple = n.toDouble
    var r = t0 - multiple * PiOver2Piece1
    var w = multiple * PiOver2Rest1 // the first piece's product is exact; its rest is not
    var head = r - w
    if !(n < 32 && ix != multipleHighWords(n - 1)) then
      // Possible cancellation: how many bits did the subtraction lose?
      val exponent = ix >> 20
      if exponent - ((highWord(head) >> 20) & 0x7ff) > 16 then
        var t = r
        w = multiple * PiOver2Piece2
        r = t - w
        w = multiple * PiOver2Rest2 - ((t - r) - w)
        head = r - w
        if exponent - ((highWord(head) >> 20) & 0x7ff) > 49 then
          t = r
          w = multiple * PiOver2Piece3
          r = t - w
          w = multiple * PiOver2Rest3 - ((t - r) - w)
          head = r - w
    val tail = (r - head) - w
    if hx < 0 then PortableMath.sineOfReduced(quarterTurns - n, -head, -tail)
    else PortableMath.sineOfReduced(quarterTurns + n, head, tail)

  /** Huge |x| (and infinities and NaN, whose result is NaN): the Payne-Hanek method. */
  private def reduceLarge(x: Double, hx: Int, ix: Int, out: Array[Double]): Int =
    if ix >= 0x7ff00000 then
      out(0) = x - x
      out(1) = out(0)
      0
    else
      // |x| as 24-bit integers times 2^(24 * k + exponentShift): its three chunks.
      val exponentShift = (ix >> 20) - 1046
      var z = fromWords(ix - (exponentShift << 20), lowWord(x))
      val chunks = new Array[Double](3)
      var k = 0
      while k < 2 do
        chunks(k) = z.toInt.toDouble
        z = (z - chunks(k)) * TwoTo24
        k += 1
      chunks(2) = z
      var count = 3
      while chunks(count - 1) == 0.0 do count -= 1
      val n = reducePayneHanek(chunks, exponentShift, count, out)
      if hx < 0 then
        out(0) = -out(0)
        out(1) = -out(1)
        -n
      else n

  /** x * 2^n for integer n, exact unless the result over- or underflows (like C's scalbn). */
  private[geometry] def scale(x: Double, n: Int): Double =
    var value = x
    var left = n
    while left > 1023 do
      value *= fromWords(0x7fe00000, 0)
      left -= 1023
    while left < -1022 do
      value *= fromWords(0x00100000, 0) // 2^-1022
      left += 1022
    value * fromWords((left + 1023) << 20, 0)

  /** The product of x = sum of `chunks(i)` * 2^(exponentShift - 24 * i) (i < count) with 2/pi,
    * modulo 4: the integer part (mod 8) is returned, the fraction times pi/2, rounded to about
    * 106 bits, goes to `out(0)` + `out(1)`. Only the chunks of 2/pi near x's binary point are
    * used: earlier ones give multiples of 8, later ones fall below the precision; when the
    * fraction comes out too small, more chunks are taken in.
    */
  private def reducePayneHanek(chunks: Array[Double], exponentShift: Int, count: Int,
      out: Array[Double]): Int =
    val terms = 4 // chunks of the product beyond the integer part, for about 106 bits
    val last = count - 1
    val first = math.max((exponentShift - 3) / 24, 0)
    var shift = exponentShift - 24 * (first + 1)
    val factors = new Array[Double](20)
    val products = new Array[Double](20)
    val digits = new Array[Int](20)
    val fractions = new Array[Double](20)

    var j = first - last
    var i = 0
    while i <= last + terms do
      factors(i) = if j < 0 then 0.0 else TwoOverPiChunks(j).toDouble
      j += 1
      i += 1
    i = 0
    while i <= terms do
      var sum = 0.0
      var m = 0
      while m <= last do
        sum += chunks(m) * factors(last + i - m)
        m += 1
      products(i) = sum
      i += 1

    var top = terms
    var n = 0
    var sign = 0 // 1 or 2 when the fraction is at least one half: then 1 - fraction is taken
    var z = 0.0
    var again = true
    while again do
      again = false
      // Cut the products into 24-bit integer digits, lowest first.
      i = 0
      j = top
      z = products(top)
      while j > 0 do
        val high = (TwoToMinus24 * z).toInt.toDouble
        digits(i) = (z - TwoTo24 * high).toInt
        z = products(j - 1) + high
        i += 1
        j -= 1
      // The integer part, modulo 8.
      z = scale(z, shift)
      z -= 8.0 * math.floor(z * 0.125)
      n = z.toInt
      z -= n.toDouble
      sign = 0
      if shift > 0 then
        val carry = digits(top - 1) >> (24 - shift)
        n += carry
        digits(top - 1) -= carry << (24 - shift)
        sign = digits(top - 1) >> (23 - shift)
      else if shift == 0 then sign = digits(top - 1) >> 23
      else if z >= 0.5 then sign = 2

      if sign > 0 then
        // The fraction is at least one half: take 1 - fraction, one more in n.
        n += 1
        var borrow = 0
        i = 0
        while i < top do
          val digit = digits(i)
          if borrow == 0 then
            if digit != 0 then
              borrow = 1
              digits(i) = 0x1000000 - digit
          else digits(i) = 0xffffff - digit
          i += 1
        if shift == 1 then digits(top - 1) &= 0x7fffff
        else if shift == 2 then digits(top - 1) &= 0x3fffff
        if sign == 2 then
          z = 1.0 - z
          if borrow != 0 then z -= scale(1.0, shift)

      if z == 0.0 then
        var any = 0
        i = top - 1
        while i >= terms do
          any |= digits(i)
          i -= 1
        if any == 0 then
          // The fraction's leading digits are all zero: take in more chunks of 2/pi.
          var more = 1
          while digits(terms - more) == 0 do more += 1
          i = top + 1
          while i <= top + more do
            factors(last + i) = TwoOverPiChunks(first + i).toDouble
            var sum = 0.0
            var m = 0
            while m <= last do
              sum += chunks(m) * factors(last + i - m)
              m += 1
            products(i) = sum
            i += 1
          top += more
          again = true

    // Drop zero digits at the end, or split the last value into digits.
    if z == 0.0 then
      top -= 1
      shift -= 24
      while digits(top) == 0 do
        top -= 1
        shift -= 24
    else
      z = scale(z, -shift)
      if z >= TwoTo24 then
        val high = (TwoToMinus24 * z).toInt.toDouble
        digits(top) = (z - TwoTo24 * high).toInt
        top += 1
        shift += 24
        digits(top) = high.toInt
      else digits(top) = z.toInt

    // The digits as doubles, then times pi/2.
    var weight = scale(1.0, shift)
    i = top
    while i >= 0 do
      products(i) = weight * digits(i).toDouble
      weight *= TwoToMinus24
      i -= 1
    i = top
    while i >= 0 do
      var sum = 0.0
      var k = 0
      while k <= terms && k <= top - i do
        sum += PiOver2Chunks(k) * products(i + k)
        k += 1
      fractions(top - i) = sum
      i -= 1

    // Sum into head and tail.
    var sum = 0.0
    i = top
    while i >= 0 do
      sum += fractions(i)
      i -= 1
    out(0) = if sign == 0 then sum else -sum
    sum = fractions(0) - sum
    i = 1
    while i <= top do
      sum += fractions(i)
      i += 1
    out(1) = if sign == 0 then sum else -sum
    n & 7
