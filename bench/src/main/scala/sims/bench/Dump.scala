package sims.bench

import java.math.{BigDecimal, MathContext, RoundingMode}
import sims.scenes.{Layout, LayoutScene, Outline}

/** Prints the layout of each scene named, one line per body and per joint and a line of
  * bounds, in the form of `scenes --dump NAME` of Box2D v3's reference program
  * (`shared/peers/box2d-v3/scenes.c`; its bounds line goes on with its own sanity thresholds,
  * which the bench does not use), so that the two can be compared with `diff`.
  */
object Dump:
  def main(args: Array[String]): Unit =
    if args.isEmpty then println("usage: Dump scene...; e.g. ballpit-500 pyramid-20 chain-100")
    for name <- args do
      Settings.scene(name) match
        case scene: LayoutScene => print(lines(scene.layout).mkString("", "\n", "\n"))
        case other => throw IllegalArgumentException(s"${other.name} is not a layout")

  /** The dump of a layout. */
  def lines(layout: Layout): Seq[String] =
    val bodies = layout.bodies.zipWithIndex.map { (b, i) =>
      val (shape, radius, halfWidth, halfHeight) = b.outline match
        case Outline.Circle(r) => ("CIRCLE", r, 0.0, 0.0)
        case Outline.Box(w, h) => ("BOX", 0.0, w, h)
      s"body $i ${if b.fixed then "static" else "dynamic"} $shape r=${g(radius)} hw=${g(halfWidth)} hh=${g(halfHeight)} " +
        s"x=${g(b.centre.x)} y=${g(b.centre.y)} d=${g(b.density)} f=${g(b.friction)} e=${g(b.restitution)} g=${b.noCollideGroup}"
    }
    val joints = layout.joints.zipWithIndex.map((j, i) => s"joint $i ${j.body1} ${j.body2} ${g(layout.length(j))}")
    val r = layout.bounds
    bodies ++ joints :+ s"bounds ${g(r.minX)} ${g(r.maxX)} ${g(r.minY)} ${g(r.maxY)}"

  /** A double as C's printf `%.17g` writes it: 17 significant digits (enough to tell any
    * two doubles apart), without trailing zeros, in exponent form only below 1e-4 or from 1e17.
    */
  def g(d: Double): String =
    if d == 0 then (if 1 / d < 0 then "-0" else "0")
    else
      val rounded = BigDecimal(d).round(MathContext(17, RoundingMode.HALF_EVEN))
      val exponent = rounded.precision - rounded.scale - 1
      if exponent < -4 || exponent >= 17 then
        val digits = rounded.unscaledValue.abs.toString.reverse.dropWhile(_ == '0').reverse
        val mantissa = if digits.length == 1 then digits else s"${digits.head}.${digits.tail}"
        f"${if d < 0 then "-" else ""}${mantissa}e${if exponent < 0 then "-" else "+"}${math.abs(exponent)}%02d"
      else rounded.stripTrailingZeros.toPlainString
