package sims.geometry

/** Elementary functions that give the same bits on every platform: the JVM, Node and browsers.
  *
  * `scala.math.sin` and its kin may differ in the last bit between platforms (the JVM's
  * `Math.sin` is an intrinsic, each JavaScript engine has its own), and a simulation
  * amplifies one bit into a different trajectory. These functions use only `+ - * /`, `sqrt`
  * and the exact bit operations on doubles, which IEEE 754 defines to the bit everywhere, and
  * follow fdlibm's algorithms, so their results are those of the JVM's `java.lang.StrictMath`
  * (which the tests check for millions of arguments). The library computes every angle that
  * reaches a world's state with them; a scene that wants the same bits on every platform uses
  * them too.
  */
object PortableMath:
  /** The upper 32 bits of `x`: sign, exponent and the first 20 bits of the fraction. */
  private[geometry] inline def highWord(x: Double): Int = (java.lang.Double.doubleToRawLongBits(x) >>> 32).toInt

  /** The lower 32 bits of `x`'s fraction. */
  private[geometry] inline def lowWord(x: Double): Int = java.lang.Double.doubleToRawLongBits(x).toInt

  /** The double whose upper and lower 32 bits are `high` and `low`. */
  private[geometry] inline def fromWords(high: Int, low: Int): Double =
    java.lang.Double.longBitsToDouble((high.toLong << 32) | (low.toLong & 0xffffffffL))

  // The thresholds of the algorithms are on high words; as doubles they compare the same way.
  private val QuarterPiBound = fromWords(0x3fe921fc, 0) // |x| below: no reduction needed
  private val TwoToMinus27 = fromWords(0x3e400000, 0)
  private val PointThreeBound = fromWords(0x3fd33333, 0)
  private val SevenTwentyFifthsBound = fromWords(0x3fe90001, 0) // above 0.78125

  /** The sine of `x` (radians), as `java.lang.StrictMath.sin`. */
  def sin(x: Double): Double =
    if math.abs(x) < QuarterPiBound then kernelSin(x, 0.0, exact = true)
    else AngleReduction.sineOf(x, 0)

  /** The cosine of `x` (radians), as `java.lang.StrictMath.cos`. */
  def cos(x: Double): Double =
    if math.abs(x) < QuarterPiBound then kernelCos(x, 0.0)
    else AngleReduction.sineOf(x, 1)

  /** sin(n * pi/2 + head + tail) for |head + tail| <= pi/4. */
  private[geometry] def sineOfReduced(n: Int, head: Double, tail: Double): Double = (n & 3) match
    case 0 => kernelSin(head, tail, exact = false)
    case 1 => kernelCos(head, tail)
    case 2 => -kernelSin(head, tail, exact = false)
    case _ => -kernelCos(head, tail)

  // Sine on [-pi/4, pi/4]: x + x^3 * (S1 + x^2 * polynomial), a minimax fit of degree 13.
  private val S1 = -1.66666666666666324348e-01
  private val S2 = 8.33333333332248946124e-03
  private val S3 = -1.98412698298579493134e-04
  private val S4 = 2.75573137070700676789e-06
  private val S5 = -2.50507602534068634195e-08
  private val S6 = 1.58969099521155010221e-10

  /** sin(x + tail) for |x| <= pi/4, where `tail` is the part of the argument below x's last bit
    * (`exact`: there is none).
    */
  private def kernelSin(x: Double, tail: Double, exact: Boolean): Double =
    if math.abs(x) < TwoToMinus27 then x
    else
      val z = x * x
      val v = z * x
      val r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))
      if exact then x + v * (S1 + z * r)
      else x - ((z * (0.5 * tail - v * r) - tail) - v * S1)

  // Cosine on [-pi/4, pi/4]: 1 - x^2/2 + x^4 * polynomial, a minimax fit of degree 14.
  private val C1 = 4.16666666666666019037e-02
  private val C2 = -1.38888888888741095749e-03
  private val C3 = 2.48015872894767294178e-05
  private val C4 = -2.75573143513906633035e-07
  private val C5 = 2.08757232129817482790e-09
  private val C6 = -1.13596475577881948265e-11

  /** cos(x + tail) for |x| <= pi/4. */
  private def kernelCos(x: Double, tail: Double): Double =
    val ax = math.abs(x)
    if ax < TwoToMinus27 then 1.0
    else
      val z = x * x
      val r = z *
        (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))))
      if ax < PointThreeBound then 1.0 - (0.5 * z - (z * r - x * tail))
      else
        // 1 - z/2 loses bits for larger x: take a round part q of z/2 off first, exactly.
        val q = if ax >= SevenTwentyFifthsBound then 0.28125 else fromWords(highWord(ax) - 0x00200000, 0)
        val hz = 0.5 * z - q
        (1.0 - q) - (hz - (z * r - x * tail))

  // atan(x) = atan(c) + atan((x - c) / (1 + x c)) for the breakpoints c = 1/2, 1, 3/2, infinity.
  private val AtanHigh = Array(4.63647609000806093515e-01, 7.85398163397448278999e-01,
    9.82793723247329054082e-01, 1.57079632679489655800e+00)
  private val AtanLow = Array(2.26987774529616870924e-17, 3.06161699786838301793e-17,
    1.39033110312309984516e-17, 6.12323399573676603587e-17)
  // atan(x) on [-7/16, 7/16]: x - x^3 * polynomial in x^2, split into odd and even terms.
  private val T0 = 3.33333333333329318027e-01
  private val T1 = -1.99999999998764832476e-01
  private val T2 = 1.42857142725034663711e-01
  private val T3 = -1.11111104054623557880e-01
  private val T4 = 9.09088713343650656196e-02
  private val T5 = -7.69187620504482999495e-02
  private val T6 = 6.66107313738753120669e-02
  private val T7 = -5.83357013379057348645e-02
  private val T8 = 4.97687799461593236017e-02
  private val T9 = -3.65315727442169155270e-02
  private val T10 = 1.62858201153657823623e-02

  /** The arc tangent of `x`, in [-pi/2, pi/2], as `java.lang.StrictMath.atan`. */
  def atan(x: Double): Double =
    val hx = highWord(x)
    val ix = hx & 0x7fffffff
    if ix >= 0x44100000 then // |x| >= 2^66, or NaN
      if x.isNaN then x + x
      else if hx > 0 then AtanHigh(3) + AtanLow(3)
      else -AtanHigh(3) - AtanLow(3)
    else
      var id = -1
      var t = x
      if ix < 0x3fdc0000 then // |x| < 7/16
        if ix < 0x3e200000 then return x // |x| < 2^-29: atan(x) rounds to x
      else
        t = math.abs(x)
        if ix < 0x3ff30000 then // |x| < 19/16
          if ix < 0x3fe60000 then
            id = 0
            t = (2.0 * t - 1.0) / (2.0 + t)
          else
            id = 1
            t = (t - 1.0) / (t + 1.0)
        else if ix < 0x40038000 then // |x| < 39/16
          id = 2
          t = (t - 1.5) / (1.0 + 1.5 * t)
        else
          id = 3
          t = -1.0 / t
      val z = t * t
      val w = z * z
      val s1 = z *
        (T0 + w * (T2 + w * (T4 + w * (T6 + w * (T8 + w * T10)))))
      val s2 = w * (T1 + w * (T3 + w * (T5 + w * (T7 + w * T9))))
      if id < 0 then t - t * (s1 + s2)
      else
        val r = AtanHigh(id) - ((t * (s1 + s2) - AtanLow(id)) - t)
        if hx < 0 then -r else r

  private val Tiny = 1.0e-300
  private val PiOver4 = 7.8539816339744827900e-01
  private val PiOver2 = 1.5707963267948965580e+00
  private val Pi = 3.1415926535897931160e+00
  private val PiLow = 1.2246467991473531772e-16 // pi - Pi

  /** The angle of the point (`x`, `y`) from the positive x axis, in [-pi, pi], as
    * `java.lang.StrictMath.atan2(y, x)`.
    */
  def atan2(y: Double, x: Double): Double =
    val hx = highWord(x)
    val ix = hx & 0x7fffffff
    val lx = lowWord(x)
    val hy = highWord(y)
    val iy = hy & 0x7fffffff
    val ly = lowWord(y)
    if x.isNaN || y.isNaN then x + y
    else if hx == 0x3ff00000 && lx == 0 then atan(y) // x = 1
    else
      val quadrant = ((hy >> 31) & 1) | ((hx >> 30) & 2) // 2 * sign(x) + sign(y)
      if (iy | ly) == 0 then
        quadrant match
          case 0 | 1 => y
          case 2 => Pi + Tiny
          case _ => -Pi - Tiny
      else if (ix | lx) == 0 then
        if hy < 0 then -PiOver2 - Tiny else PiOver2 + Tiny
      else if ix == 0x7ff00000 then
        if iy == 0x7ff00000 then
          quadrant match
            case 0 => PiOver4 + Tiny
            case 1 => -PiOver4 - Tiny
            case 2 => 3.0 * PiOver4 + Tiny
            case _ => -3.0 * PiOver4 - Tiny
        else
          quadrant match
            case 0 => 0.0
            case 1 => -0.0
            case 2 => Pi + Tiny
            case _ => -Pi - Tiny
      else if iy == 0x7ff00000 then
        if hy < 0 then -PiOver2 - Tiny else PiOver2 + Tiny
      else
        val k = (iy - ix) >> 20
        val z =
          if k > 60 then PiOver2 + 0.5 * PiLow // |y/x| > 2^60
          else if hx < 0 && k < -60 then 0.0 // |y|/x < -2^60
          else atan(math.abs(y / x))
        quadrant match
          case 0 => z
          case 1 => -z
          case 2 => Pi - (z - PiLow)
          case _ => (z - PiLow) - Pi

  // acos near 0: pi/2 - (x + x^3 R(x^2)), R a rational minimax fit.
  private val PiOver2High = 1.57079632679489655800e+00
  private val PiOver2Low = 6.12323399573676603587e-17
  private val P0 = 1.66666666666666657415e-01
  private val P1 = -3.25565818622400915405e-01
  private val P2 = 2.01212532134862925881e-01
  private val P3 = -4.00555345006794114027e-02
  private val P4 = 7.91534994289814532176e-04
  private val P5 = 3.47933107596021167570e-05
  private val Q1 = -2.40339491173441421878e+00
  private val Q2 = 2.02094576023350569471e+00
  private val Q3 = -6.88283971605453293030e-01
  private val Q4 = 7.70381505559019352791e-02

  /** R(z) = p(z) / q(z) of the arc sine's expansion asin(x) = x + x^3 R(x^2). */
  private def arcSineRatio(z: Double): Double =
    val p = z *
      (P0 + z * (P1 + z * (P2 + z * (P3 + z * (P4 + z * P5)))))
    val q = 1.0 + z * (Q1 + z * (Q2 + z * (Q3 + z * Q4)))
    p / q

  /** The arc cosine of `x`, in [0, pi] (NaN outside [-1, 1]), as `java.lang.StrictMath.acos`. */
  def acos(x: Double): Double =
    val hx = highWord(x)
    val ix = hx & 0x7fffffff
    if ix >= 0x3ff00000 then // |x| >= 1
      if ix == 0x3ff00000 && lowWord(x) == 0 then
        if hx > 0 then 0.0 else Pi + 2.0 * PiOver2Low
      else (x - x) / (x - x) // NaN
    else if ix < 0x3fe00000 then // |x| < 1/2
      if ix <= 0x3c600000 then PiOver2High + PiOver2Low // |x| < 2^-57
      else PiOver2High - (x - (PiOver2Low - x * arcSineRatio(x * x)))
    else if hx < 0 then // x < -1/2: acos(x) = pi - 2 asin(sqrt((1 + x) / 2))
      val z = (1.0 + x) * 0.5
      val s = math.sqrt(z)
      val w = arcSineRatio(z) * s - PiOver2Low
      Pi - 2.0 * (s + w)
    else // x > 1/2: acos(x) = 2 asin(sqrt((1 - x) / 2)), the root split for precision
      val z = (1.0 - x) * 0.5
      val s = math.sqrt(z)
      val head = fromWords(highWord(s), 0)
      val correction = (z - head * head) / (s + head)
      val w = arcSineRatio(z) * s + correction
      2.0 * (head + w)

  /** sqrt(x^2 + y^2) without overflow or underflow in between, as `java.lang.StrictMath.hypot`. */
  def hypot(x: Double, y: Double): Double =
    var ha = highWord(x) & 0x7fffffff
    var hb = highWord(y) & 0x7fffffff
    var a = math.abs(x)
    var b = math.abs(y)
    if hb > ha then
      val swap = a
      a = b
      b = swap
      val swapHigh = ha
      ha = hb
      hb = swapHigh
    if ha - hb > 0x3c00000 then a + b // a / b > 2^60
    else
      var k = 0
      if ha > 0x5f300000 then // a > 2^500
        if ha >= 0x7ff00000 then // infinity or NaN: infinity wins over NaN
          var w = a + b
          if ((ha & 0xfffff) | lowWord(a)) == 0 then w = a
          if ((hb ^ 0x7ff00000) | lowWord(b)) == 0 then w = b
          return w
        // Scale both by 2^-600.
        ha -= 0x25800000
        hb -= 0x25800000
        k += 600
        a = fromWords(ha, lowWord(a))
        b = fromWords(hb, lowWord(b))
      if hb < 0x20b00000 then // b < 2^-500
        if hb <= 0x000fffff then // b subnormal or zero
          if (hb | lowWord(b)) == 0 then return a
          val twoTo1022 = fromWords(0x7fd00000, 0)
          b *= twoTo1022
          a *= twoTo1022
          k -= 1022
        else // scale both by 2^600
          ha += 0x25800000
          hb += 0x25800000
          k -= 600
          a = fromWords(ha, lowWord(a))
          b = fromWords(hb, lowWord(b))
      // Now a and b are of moderate size: sqrt(a^2 + b^2) with a^2 split into exact parts.
      var w = a - b
      if w > b then
        val t1 = fromWords(ha, 0)
        val t2 = a - t1
        w = math.sqrt(t1 * t1 - (b * (-b) - t2 * (a + t1)))
      else
        a = a + a
        val y1 = fromWords(hb, 0)
        val y2 = b - y1
        val t1 = fromWords(ha + 0x00100000, 0)
        val t2 = a - t1
        w = math.sqrt(t1 * y1 - (w * (-w) - (t1 * y2 + t2 * b)))
      if k != 0 then fromWords(0x3ff00000 + (k << 20), 0) * w else w
