package sims.bench

/** The benchmark scenes, described once as plain numbers so that every engine builds exactly
  * the same bodies (positions, sizes, material) from them.
  *
  * Common settings: gravity (0, -9.81), time step 1/60, 10 velocity and 10 position
  * iterations, friction 0.5, restitution 0, density 1; the peers run with sleeping and
  * continuous collision detection off (SiMS has neither).
  */
object Scenes:
  /** Gravity along y, m/s^2. */
  val Gravity: Double = -9.81
  /** Time step, s. */
  val TimeStep: Double = 1.0 / 60
  /** Velocity and position iterations. */
  val Iterations: Int = 10
  /** Friction of every contact (SiMS: the product of the two shapes' values). */
  val Friction: Double = 0.5
  /** Restitution of every contact. */
  val Restitution: Double = 0.0
  /** Density of every shape, kg/m^2. */
  val Density: Double = 1.0
  /** Steps simulated before any measurement. */
  val WarmUpSteps: Int = 300

  /** A fixed box: centre and half extents. */
  final case class StaticBox(x: Double, y: Double, halfWidth: Double, halfHeight: Double)

  /** Ballpit: balls of radius 0.1 on a grid of spacing 0.22, 45 per row, in a container 10 m
    * wide inside (floor top at y = 0, inner wall faces at x = -5 and 5).
    */
  object Ballpit:
    /** Ball radius, m. */
    val Radius: Double = 0.1
    /** Grid spacing, m. */
    val Spacing: Double = 0.22
    /** Balls per row. */
    val PerRow: Int = 45
    /** Half the inner width of the container, m. */
    val HalfWidth: Double = 5.0
    /** Largest sideways offset of a ball from its grid column, m. */
    val MaxOffset: Double = 0.005
    /** Seed of the offsets (the same in every engine). */
    val Seed: Long = 20091130L
    /** The sizes benchmarked. */
    val Sizes: Seq[Int] = Seq(500, 1000, 2000, 4000, 8000, 16000)

    /** Rows needed for n balls. */
    def rows(n: Int): Int = (n + PerRow - 1) / PerRow

    /** Height of the walls, m: the initial stack plus 2 m. */
    def wallHeight(n: Int): Double = rows(n) * Spacing + 2

    /** Floor and walls (1 m thick). */
    def container(n: Int): Seq[StaticBox] =
      val h = wallHeight(n)
      Seq(
        StaticBox(0, -0.5, HalfWidth + 1, 0.5),
        StaticBox(-HalfWidth - 0.5, h / 2, 0.5, h / 2),
        StaticBox(HalfWidth + 0.5, h / 2, 0.5, h / 2))

    /** Initial centres (x0, y0, x1, y1, ...) of the n balls, row by row from the floor up. */
    def centres(n: Int): Array[Double] =
      val random = java.util.Random(Seed)
      val out = new Array[Double](2 * n)
      var i = 0
      while i < n do
        val column = i % PerRow
        val row = i / PerRow
        val offset = (random.nextDouble() * 2 - 1) * MaxOffset
        out(2 * i) = -HalfWidth + Spacing / 2 + column * Spacing + offset
        out(2 * i + 1) = Radius + 0.02 + row * Spacing
        i += 1
      out

  /** Pyramid: a ground box and 20 rows of 0.5 m boxes (210 boxes). */
  object Pyramid:
    /** Rows of the pyramid. */
    val Rows: Int = 20
    /** Half side of a box, m. */
    val HalfSide: Double = 0.25
    /** Horizontal distance of neighbouring boxes' centres, m. */
    val Spacing: Double = 0.5625
    /** The ground box. */
    val ground: StaticBox = StaticBox(0, -0.5, 40, 0.5)

    /** Initial centres (x0, y0, ...) of the boxes, bottom row first. */
    def centres: Array[Double] =
      val out = Array.newBuilder[Double]
      for row <- 0 until Rows do
        val count = Rows - row
        for j <- 0 until count do
          out += (j - (count - 1) / 2.0) * Spacing
          out += HalfSide + row * 2 * HalfSide
      out.result()

  /** Chain: 100 circles of radius 0.05, 0.2 m apart on a horizontal line, joined by distance
    * joints between neighbouring centres; the first is fixed; links never collide.
    */
  object Chain:
    /** Number of links. */
    val Links: Int = 100
    /** Link radius, m. */
    val Radius: Double = 0.05
    /** Distance of neighbouring links, m. */
    val Spacing: Double = 0.2

    /** Initial centre of link i. */
    def x(i: Int): Double = i * Spacing
    /** Height of the chain, m. */
    val y: Double = 10.0

  /** BallStack, the original SiMS example (SiMS only): the examples' scene
    * `sims.scenes.BallStack` itself (ground, walls 3.5 m apart inside, 52 balls of
    * radius 0.2, SiMS's default materials). The numbers here are for the sanity check.
    */
  object BallStack:
    /** Ball radius, m. */
    val Radius: Double = 0.2
    /** Half the inner width between the walls, m. */
    val HalfWidth: Double = 1.5
    /** Height of the walls, m. */
    val Height: Double = 4.0

  /** The scene names: ballpit-N for each size, pyramid-20, chain-100, ballstack. */
  val names: Seq[String] = Ballpit.Sizes.map(n => s"ballpit-$n") ++ Seq("pyramid-20", "chain-100", "ballstack")

  /** Number of balls of a ballpit scene name. */
  def ballpitSize(name: String): Option[Int] =
    if name.startsWith("ballpit-") then name.stripPrefix("ballpit-").toIntOption else None
