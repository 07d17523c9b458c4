package sims.solver

import scala.collection.mutable.ArrayBuffer
import sims.Defaults
import sims.collision.{PairFilter, TimeOfImpact}
import sims.dynamics.{Body, Shape, World}

/** Continuous collision of bullets (`Body.bullet`) against fixed shapes, a stage at the end of
  * either step: a bullet's motion over the step, from its placement at the start to its
  * placement at the end, is swept against the fixed shapes near its path (the world's query grid
  * over the box around both placements, grown by the body's extent), and if a shape of the body
  * meets one of them on the way ([[sims.collision.TimeOfImpact]]), the body is moved back to the
  * first such meeting, reaching [[Defaults.BulletDepth]] into the fixed shape, with its
  * velocities as they are: the next step's contact stops it there. A body fast enough to cross a
  * thin wall between two steps thus never passes it. Nor does its centre's path enter a fixed
  * shape: a spinning body's corners can reach deeper than the time of impact sees, and a body
  * whose centre got into the tip of a closed wedge was pushed out on its far side.
  *
  * Only free bullets are swept, only against fixed shapes (as Box2D's bullets against static
  * ones; two fast bodies can still pass each other), and only pairs that may collide
  * ([[PairFilter]]): a world without bullets skips the stage, and its results do not change.
  */
private[sims] final class ContinuousCollision:
  private var bullets = new Array[Body](4)
  private var startX, startY, startAngle = new Array[Double](4)
  private var count = 0
  private val near = ArrayBuffer.empty[Shape]
  private val impact = TimeOfImpact()
  private val centrePath = sims.geometry.RayMath.Hit()

  /** Number of bodies moved back by the last `sweep` (for tests and measurements). */
  var stopped: Int = 0

  /** Records where every free bullet of `world` is at the start of a step. */
  def begin(world: World): Unit =
    count = 0
    val bodies = world.bodyList
    var i = 0
    while i < bodies.length do
      val b = bodies(i)
      if b.bullet && !b.fixed then
        if count == bullets.length then
          val capacity = 2 * count
          bullets = java.util.Arrays.copyOf(bullets, capacity)
          startX = java.util.Arrays.copyOf(startX, capacity)
          startY = java.util.Arrays.copyOf(startY, capacity)
          startAngle = java.util.Arrays.copyOf(startAngle, capacity)
        bullets(count) = b
        startX(count) = b.x
        startY(count) = b.y
        startAngle(count) = b.angle
        count += 1
      i += 1

  /** Moves back every bullet recorded by `begin` whose motion since met a fixed shape. */
  def sweep(world: World): Unit =
    stopped = 0
    var k = 0
    while k < count do
      val b = bullets(k)
      if (b.world eq world) && !b.fixed then sweepOne(world, b, startX(k), startY(k), startAngle(k))
      bullets(k) = null
      k += 1
    count = 0

  private def sweepOne(world: World, body: Body, x0: Double, y0: Double, angle0: Double): Unit =
    val (x1, y1, angle1) = (body.x, body.y, body.angle)
    val dx = x1 - x0
    val dy = y1 - y0
    val dAngle = angle1 - angle0
    if dx != 0 || dy != 0 || dAngle != 0 then
      val reach = body.extent
      near.clear()
      world.shapesNear(math.min(x0, x1) - reach, math.min(y0, y1) - reach, math.max(x0, x1) + reach,
        math.max(y0, y1) + reach, near)
      var first = 1.0
      val shapes = body.shapes
      var s = 0
      while s < shapes.length do
        val shape = shapes(s)
        var n = 0
        while n < near.length do
          val other = near(n)
          if other.body.fixed && PairFilter.accepts(shape, other) then
            first = impact.fraction(body, x0, y0, angle0, dx, dy, dAngle, shape, other, Defaults.BulletDepth, first)
            // The body's centre never crosses into the fixed shape, whatever its turn did (a
            // spinning body's corners can reach deeper than its time of impact sees).
            if other.castRay(x0, y0, dx, dy, first, centrePath) then first = centrePath.fraction
          n += 1
        s += 1
      if first < 1 then
        body.x = x0 + first * dx
        body.y = y0 + first * dy
        body.angle = angle0 + first * dAngle
        stopped += 1
      else
        body.x = x1
        body.y = y1
        body.angle = angle1
      body.placeShapes()
