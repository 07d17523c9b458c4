package sims.sweep.examples

import java.awt.{BasicStroke, Color, Font, RenderingHints}
import java.awt.image.BufferedImage
import sims.sweep.ResultTable

/** Draws a sweep's table as small multiples: one heat map of `value` over `x` and `y` for each
  * value of `panel`, side by side with one colour scale (java.awt only: no plotting library).
  */
object Heatmaps:
  private val Cell = 14
  private val Margin = 56
  private val Gap = 22
  private val TitleHeight = 40
  private val PanelsPerLine = 5

  /** The picture; every (panel, x, y) combination must be in the table once. */
  def draw(table: ResultTable, x: String, y: String, panel: String, value: String, title: String): BufferedImage =
    val xs = table(x).distinct.sorted
    val ys = table(y).distinct.sorted
    val panels = table(panel).distinct.sorted
    val values = table(value)
    val cells = table(x).indices.map(i => (table(panel)(i), table(x)(i), table(y)(i)) -> values(i)).toMap
    require(cells.size == table.size, s"each ($panel, $x, $y) must be in the table once")
    for p <- panels; vx <- xs; vy <- ys do
      require(cells.contains((p, vx, vy)), s"the table has no run with $panel = $p, $x = $vx, $y = $vy")
    val top = values.filterNot(_.isNaN).maxOption.getOrElse(0.0) max 1.0
    val panelWidth = xs.size * Cell
    val panelHeight = ys.size * Cell
    val lines = (panels.size + PanelsPerLine - 1) / PanelsPerLine
    val columns = panels.size min PanelsPerLine
    val width = Margin + columns * (panelWidth + Gap) + 90
    val height = TitleHeight + lines * (panelHeight + Gap + 34) + 30
    val image = BufferedImage(width, height, BufferedImage.TYPE_INT_RGB)
    val g = image.createGraphics()
    g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON)
    g.setColor(Color.WHITE)
    g.fillRect(0, 0, width, height)
    g.setColor(Color.BLACK)
    g.setFont(Font(Font.SANS_SERIF, Font.BOLD, 15))
    g.drawString(title, Margin, 24)
    g.setFont(Font(Font.SANS_SERIF, Font.PLAIN, 11))
    for (p, k) <- panels.zipWithIndex do
      val left = Margin + (k % PanelsPerLine) * (panelWidth + Gap)
      val upper = TitleHeight + (k / PanelsPerLine) * (panelHeight + Gap + 34) + 14
      g.setColor(Color.BLACK)
      g.drawString(s"$panel ${number(p)}", left, upper - 4)
      for (vx, i) <- xs.zipWithIndex; (vy, j) <- ys.zipWithIndex do
        g.setColor(colour(cells((p, vx, vy)) / top))
        // y grows upwards: the first value at the bottom.
        g.fillRect(left + i * Cell, upper + (ys.size - 1 - j) * Cell, Cell, Cell)
      g.setColor(Color.GRAY)
      g.setStroke(BasicStroke(1))
      g.drawRect(left, upper, panelWidth, panelHeight)
      g.setColor(Color.BLACK)
      g.drawString(number(xs.head), left, upper + panelHeight + 12)
      val last = number(xs.last)
      g.drawString(last, left + panelWidth - g.getFontMetrics.stringWidth(last), upper + panelHeight + 12)
      g.drawString(x, left + (panelWidth - g.getFontMetrics.stringWidth(x)) / 2, upper + panelHeight + 24)
      if k % PanelsPerLine == 0 then
        g.drawString(number(ys.last), left - 6 - g.getFontMetrics.stringWidth(number(ys.last)), upper + 10)
        g.drawString(number(ys.head), left - 6 - g.getFontMetrics.stringWidth(number(ys.head)), upper + panelHeight)
        val rotated = g.getTransform
        g.rotate(-math.Pi / 2, left - 30, upper + panelHeight / 2)
        g.drawString(y, left - 30 - g.getFontMetrics.stringWidth(y) / 2, upper + panelHeight / 2)
        g.setTransform(rotated)
    // The colour scale, 0 at the bottom and the largest value at the top.
    val scaleLeft = Margin + columns * (panelWidth + Gap) + 10
    val scaleTop = TitleHeight + 14
    val scaleHeight = lines * (panelHeight + Gap + 34) - Gap - 34
    for i <- 0 until scaleHeight do
      g.setColor(colour(1 - i.toDouble / (scaleHeight - 1)))
      g.fillRect(scaleLeft, scaleTop + i, 16, 1)
    g.setColor(Color.BLACK)
    g.drawString(number(top), scaleLeft + 20, scaleTop + 10)
    g.drawString("0", scaleLeft + 20, scaleTop + scaleHeight)
    g.drawString(value, scaleLeft, scaleTop + scaleHeight + 16)
    g.dispose()
    image

  private def number(v: Double): String =
    if v == math.rint(v) && math.abs(v) < 1e9 then v.toLong.toString else f"$v%.2f".stripSuffix("0")

  // A dark-to-light scale (dark blue, teal, green, yellow) that reads in grey too.
  private val Stops = IndexedSeq(Color(40, 20, 90), Color(35, 110, 140), Color(50, 170, 110), Color(250, 230, 60))

  /** The colour of `t` in [0, 1]; a value that is not a number is grey. */
  private def colour(t: Double): Color =
    if t.isNaN then Color.LIGHT_GRAY
    else
      val s = (t max 0.0 min 1.0) * (Stops.size - 1)
      val i = math.min(s.toInt, Stops.size - 2)
      val f = s - i
      def mixed(a: Int, b: Int) = math.round(a + (b - a) * f).toInt
      val (a, b) = (Stops(i), Stops(i + 1))
      Color(mixed(a.getRed, b.getRed), mixed(a.getGreen, b.getGreen), mixed(a.getBlue, b.getBlue))
