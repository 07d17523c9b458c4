package sims.solver.soft

/** The dense block arithmetic [[JointTrees]] shares between its block shapes: inverting a
  * block and multiplying a vector by one, for matrices of at most 3 x 3 stored row-major with
  * stride 3 at an offset of a Double array. No allocation.
  */
private[soft] object SmallMatrix:
  /** dst = src^-1 for the n x n block at src(so) (n from 1 to 3); singular blocks give 0. Only
    * the n x n block of dst is written: its other entries are never read, so they are not
    * cleared (JMH, chain-100: 117 and 120 µs per step against 119 and 132 with the clearing).
    */
  def invert(src: Array[Double], so: Int, n: Int, dst: Array[Double], dO: Int): Unit =
    n match
      case 1 =>
        val a = src(so)
        dst(dO) = if a != 0 then 1 / a else 0
      case 2 =>
        val a = src(so); val b = src(so + 1); val c = src(so + 3); val e = src(so + 4)
        var det = a * e - b * c
        if det != 0 then det = 1 / det
        dst(dO) = e * det; dst(dO + 1) = -b * det
        dst(dO + 3) = -c * det; dst(dO + 4) = a * det
      case _ =>
        val a11 = src(so); val a12 = src(so + 1); val a13 = src(so + 2)
        val a21 = src(so + 3); val a22 = src(so + 4); val a23 = src(so + 5)
        val a31 = src(so + 6); val a32 = src(so + 7); val a33 = src(so + 8)
        val c11 = a22 * a33 - a23 * a32
        val c12 = a23 * a31 - a21 * a33
        val c13 = a21 * a32 - a22 * a31
        var det = a11 * c11 + a12 * c12 + a13 * c13
        if det != 0 then det = 1 / det
        dst(dO) = c11 * det
        dst(dO + 1) = (a13 * a32 - a12 * a33) * det
        dst(dO + 2) = (a12 * a23 - a13 * a22) * det
        dst(dO + 3) = c12 * det
        dst(dO + 4) = (a11 * a33 - a13 * a31) * det
        dst(dO + 5) = (a13 * a21 - a11 * a23) * det
        dst(dO + 6) = c13 * det
        dst(dO + 7) = (a12 * a31 - a11 * a32) * det
        dst(dO + 8) = (a11 * a22 - a12 * a21) * det

  /** x(xo) = A z(zo) for the n x n block A at a(ao). */
  def multiply(a: Array[Double], ao: Int, n: Int, z: Array[Double], zo: Int, x: Array[Double], xo: Int): Unit =
    var i = 0
    while i < n do
      var sum = 0.0
      var k = 0
      while k < n do
        sum += a(ao + 3 * i + k) * z(zo + k)
        k += 1
      x(xo + i) = sum
      i += 1
