package sims.scenes

import sims.dynamics.{Body, Circle, Rectangle, RegularPolygon, World}
import sims.dynamics.joints.{DistanceJoint, SpringJoint}
import sims.geometry.Vector2D

/** The scenes the tests pin down: the golden scenes, whose every body's doubles after 240
  * steps are asserted bit for bit (`PerformanceRegressionSpec`), and the determinism scene.
  * They are built exactly as when their hashes were recorded (same bodies, order, materials
  * and seeds): change nothing here without a new hash, and never update a hash silently.
  */
object TestScenes:
  /** The golden scenes, by name. The golden pyramid is the benchmark's `pyramid-12`. */
  val golden: Seq[(String, Scene)] = Seq(
    "golden-ballpit-300" -> GoldenBallpit, "golden-pyramid-12" -> BoxPyramid(12), "golden-mixed" -> GoldenMixed)

  /** The test scene with this name, ignoring case: a golden one, or `determinism` (its
    * bodies created in their own order).
    */
  def find(name: String): Option[Scene] =
    golden.collectFirst { case (n, scene) if n.equalsIgnoreCase(name) => scene }
      .orElse(Option.when(name.equalsIgnoreCase(Determinism.Name))(Determinism(0 until Determinism.Bodies)))

  /** golden-ballpit-300: 300 balls of radius 0.1 on a jittered grid (20 to a row) in a
    * container 4.5 m wide inside (another ball pit than the benchmark's).
    */
  object GoldenBallpit extends LayoutScene:
    private val Balls = 300
    def name: String = "golden-ballpit-300"
    def description: String = s"$Balls balls in a container 4.5 m wide (a golden scene)."
    def view: Region = Region(-4, -1, 4, 10.5)

    lazy val layout: Layout =
      def fixedBox(x: Double, y: Double, halfWidth: Double, halfHeight: Double) =
        SceneBody.box(Vector2D(x, y), halfWidth, halfHeight, fixed = true)
      val random = java.util.Random(7)
      val balls =
        for i <- 0 until Balls yield
          val centre = Vector2D(-2.2 + (i % 20) * 0.22 + (random.nextDouble() * 2 - 1) * 0.005, 0.12 + (i / 20) * 0.22)
          SceneBody.circle(centre, 0.1)
      Layout(IndexedSeq(fixedBox(0, -0.5, 3.5, 0.5), fixedBox(-2.75, 5, 0.5, 5), fixedBox(2.75, 5, 0.5, 5)) ++ balls,
        IndexedSeq.empty, Layout.StandardGravity, Layout.StandardTimeStep, Region(-2.25, 0, 2.25, 10))

  /** golden-mixed: triangles, hexagons, circles, rotated boxes, a body of two shapes and a
    * short chain hanging from a fixed ball, dropped into a container; default materials except
    * the container's (friction 0.5 for a pair of its own value, restitution 0).
    */
  object GoldenMixed extends Scene:
    def name: String = "golden-mixed"
    def description: String = "Mixed shapes, a two-shape body and a chain in a container (a golden scene)."
    def view: Region = Region(-4.5, -1, 4.5, 6.5)

    private def fixedBox(x: Double, y: Double, halfWidth: Double, halfHeight: Double): Body =
      val r = Rectangle(halfWidth, halfHeight, 1)
      r.pos = Vector2D(x, y)
      r.friction = math.sqrt(0.5)
      r.restitution = 0
      val b = r.asBody
      b.fixed = true
      b

    def build(): Staged =
      val world = World()
      world += fixedBox(0, -0.5, 4, 0.5)
      world += fixedBox(-3.5, 3, 0.5, 3)
      world += fixedBox(3.5, 3, 0.5, 3)
      for i <- 0 until 24 do
        val x = -2.5 + (i % 6) * 0.9
        val y = 0.6 + (i / 6) * 0.9
        val shape = i % 4 match
          case 0 => RegularPolygon(3, 0.3, 1)
          case 1 => RegularPolygon(6, 0.3, 2)
          case 2 => Circle(0.25, 1)
          case _ =>
            val r = Rectangle(0.3, 0.15, 1)
            r.rotation = 0.3 * i
            r
        shape.pos = Vector2D(x, y)
        world += shape.asBody
      val left = Circle(0.2, 1)
      left.pos = Vector2D(-1, 5)
      val right = Rectangle(0.3, 0.1, 1)
      right.pos = Vector2D(-0.5, 5.1)
      right.rotation = 0.5
      world += Body(left, right)
      val anchor = Circle(0.05, 1)
      anchor.pos = Vector2D(1.5, 5.5)
      val fixed = anchor.asBody
      fixed.fixed = true
      world += fixed
      var previous = fixed
      for i <- 1 to 5 do
        val link = Circle(0.08, 1)
        link.pos = Vector2D(1.5 + 0.3 * i, 5.5)
        val b = link.asBody
        world += b
        world += DistanceJoint(previous, previous.pos, b, b.pos)
        previous = b
      Staged(world)

  /** `determinism`: circles, boxes and pentagons on the ground with a distance joint and a
    * spring. `allocationOrder` permutes the order in which the bodies are created (and so
    * their identity hash codes), never the order in which they join the world.
    */
  final case class Determinism(allocationOrder: Seq[Int]) extends Scene:
    require(allocationOrder.sorted == (0 until Determinism.Bodies), s"not an order of the bodies: $allocationOrder")
    def name: String = Determinism.Name
    def description: String = "Mixed shapes on the ground with a joint and a spring (bodies created in a given order)."
    def view: Region = Region(-3.5, -1, 3.5, 4)

    def build(): Staged =
      val world = World()
      val created = Array.ofDim[Body](Determinism.Bodies)
      for i <- allocationOrder do
        val shape = i % 3 match
          case 0 => Circle(0.2 + 0.01 * i, 1)
          case 1 => Rectangle(0.2, 0.15, 1)
          case _ => RegularPolygon(5, 0.25, 1)
        shape.pos = Vector2D(-1.5 + (i % 4) * 0.9 + 0.05 * (i / 4), 0.4 + (i / 4) * 0.7)
        created(i) = shape.asBody
      world += Scene.ground(3)
      created.foreach(world += _)
      world += DistanceJoint(created(0), created(0).pos, created(5), created(5).pos)
      world += SpringJoint(created(1), created(2), 30)
      Staged(world)

  object Determinism:
    /** The scene's name. */
    val Name = "determinism"
    /** Number of bodies created in the given order (the ground comes on top of them). */
    val Bodies = 12
