package sims.robustness

import org.scalacheck.{Gen, Shrink}
import sims.dynamics.{Circle, Rectangle, RegularPolygon, Shape, World}
import sims.dynamics.joints.{DistanceJoint, SpringJoint}
import sims.geometry.Vector2D
import sims.solver.Solver

/** Random scenes for the fuzz tests and the save-and-load tests: recipes drawn by ScalaCheck,
  * built into worlds.
  */
object RandomScenes:
  /** The recipe of one body: kind, size (0.05 to 5 m), density, position, velocities, material. */
  final case class BodySpec(kind: Int, size: Double, density: Double, x: Double, y: Double,
      vx: Double, vy: Double, w: Double, restitution: Double, friction: Double, fixed: Boolean)

  /** Random body recipes. */
  val bodySpec: Gen[BodySpec] =
    for
      kind <- Gen.choose(0, 2)
      size <- Gen.choose(math.log(0.05), math.log(5.0)).map(math.exp)
      density <- Gen.choose(math.log(0.1), math.log(10.0)).map(math.exp)
      x <- Gen.choose(-10.0, 10.0)
      y <- Gen.choose(-10.0, 10.0)
      vx <- Gen.choose(-10.0, 10.0)
      vy <- Gen.choose(-10.0, 10.0)
      w <- Gen.choose(-5.0, 5.0)
      restitution <- Gen.choose(0.0, 1.0)
      friction <- Gen.choose(0.0, 1.0)
      fixed <- Gen.frequency(9 -> false, 1 -> true)
    yield BodySpec(kind, size, density, x, y, vx, vy, w, restitution, friction, fixed)

  /** A scene's recipe: bodies, and joints as (body index, body index, spring?). */
  type SceneSpec = (List[BodySpec], List[(Int, Int, Boolean)])

  /** Scene recipes of 2 to 14 bodies and up to 6 joints. */
  val sceneSpec: Gen[SceneSpec] =
    for
      n <- Gen.choose(2, 14)
      bodies <- Gen.listOfN(n, bodySpec)
      joints <- Gen.listOf(for a <- Gen.choose(0, n - 1); b <- Gen.choose(0, n - 1); s <- Gen.oneOf(true, false) yield (a, b, s))
    yield (bodies, joints.filter((a, b, _) => a != b).take(6))

  // Shrinking would break the recipes' invariants (joint indices, distinct bodies).
  given Shrink[SceneSpec] = Shrink.shrinkAny

  /** The world of a recipe, with or without gravity and springs, stepped by `solver`. */
  def build(spec: SceneSpec, gravity: Boolean, springs: Boolean,
      solver: Solver): World =
    val world = World()
    world.solver = solver
    if !gravity then world.gravity = Vector2D.Null
    val bodies = spec._1.map { s =>
      val shape: Shape = s.kind match
        case 0 => Circle(s.size, s.density)
        case 1 => Rectangle(s.size, s.size * 0.6, s.density)
        case _ => RegularPolygon(3 + (s.size * 10).toInt % 6, s.size, s.density)
      shape.pos = Vector2D(s.x, s.y)
      shape.restitution = s.restitution
      shape.friction = s.friction
      val b = shape.asBody
      b.linearVelocity = Vector2D(s.vx, s.vy)
      b.angularVelocity = s.w
      b.fixed = s.fixed
      world += b
      b
    }
    for (a, b, spring) <- spec._2 if a != b && a < bodies.size && b < bodies.size do
      val (p, q) = (bodies(a), bodies(b))
      // Stiffness scaled to the lighter body keeps the explicit spring stable (period ~1.4 s).
      if spring && springs then world += SpringJoint(p, q, 20 * math.min(p.mass, q.mass).min(1e6))
      else if !spring && (p.pos - q.pos).length > 1e-6 then world += DistanceJoint(p, p.pos, q, q.pos)
    world

  /** Whether every body's placement and velocities are finite. */
  def finite(world: World): Boolean = world.bodies.forall(b =>
    b.pos.isFinite && b.linearVelocity.isFinite && !b.rotation.isNaN && !b.angularVelocity.isNaN)
