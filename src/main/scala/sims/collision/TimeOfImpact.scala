package sims.collision

import sims.geometry.PortableMath

import sims.Defaults
import sims.dynamics.{Body, Circle, Shape}

/** When a shape of a moving body first meets a fixed shape during one step: conservative
  * advancement (Mirtich's; Box2D's bullets answer the same question by root finding).
  *
  * The body's placement moves linearly from (x0, y0, angle0) at fraction 0 to (x0 + dx,
  * y0 + dy, angle0 + dAngle) at fraction 1. At a fraction t the two shapes are `s` apart along
  * the normal n from the fixed shape ([[ShapeSeparation]]); no point of the moving shape can
  * close that gap faster than `rate = -(dx, dy) . n + |dAngle| reach` per unit of fraction (reach:
  * how far the shape's outline lies from the body's centre; a circle's own turning moves
  * nothing), so until t' they stay at least `s - rate (t' - t)` apart, and advancing to
  * `t' = t + (s - target) / rate` never passes the target separation, however thin the fixed
  * shape. Repeated, t converges to the first fraction at which the separation reaches the target
  * (a slight overlap, [[Defaults.BulletDepth]]). A motion away or along the surface (rate at
  * most 0) never meets it.
  *
  * Pairs already touching at the start (at most [[Defaults.ContactHysteresis]] apart: a bullet
  * rolling on the ground, resting against a wall) are left to the step's contacts, which hold
  * them; advancing along a surface it touches would stop a rolling body for nothing.
  */
private[sims] final class TimeOfImpact:
  private val separation = ShapeSeparation()

  /** Whether the last `fraction` stopped after [[Defaults.BulletIterations]] steps, short of
    * the target (a fast-turning shape grazing a corner closes in slowly): its fraction is then
    * where the search got to, before the meeting, never past it.
    */
  var stoppedShort: Boolean = false

  /** The fraction in [0, limit) at which `moving` (a shape of `body`) first reaches the
    * separation `-depth` from the fixed shape `fixed`, or `limit` if it does not before `limit`
    * (also when the two touch at the start already, or when a shape is of a kind
    * [[ShapeSeparation]] does not know). Moves the body
    * along its motion while it searches: the caller places it afterwards.
    */
  def fraction(body: Body, x0: Double, y0: Double, angle0: Double, dx: Double, dy: Double, dAngle: Double,
      moving: Shape, fixed: Shape, depth: Double, limit: Double): Double =
    val target = -depth
    val turning = math.abs(dAngle) * reach(body, moving)
    stoppedShort = false
    place(body, x0, y0, angle0, dx, dy, dAngle, 0)
    if !separation.measure(fixed, moving) || separation.distance <= Defaults.ContactHysteresis then limit
    else
      var t = 0.0
      var result = -1.0
      var iteration = 0
      while result < 0 do
        val rate = turning - (dx * separation.normalX + dy * separation.normalY)
        if rate <= 0 then result = limit // moving away or along: the gap along n never closes
        else
          t += (separation.distance - target) / rate
          if t >= limit then result = limit
          else
            place(body, x0, y0, angle0, dx, dy, dAngle, t)
            iteration += 1
            if !separation.measure(fixed, moving) then result = limit
            else if separation.distance <= target + Defaults.BulletTolerance then result = t
            else if iteration == Defaults.BulletIterations then
              stoppedShort = true
              result = t
      result

  /** The farthest a point of `shape`'s outline lies from `body`'s centre, as far as turning the
    * body moves it: its centre's distance, plus its bounding radius unless it is a circle.
    */
  private def reach(body: Body, shape: Shape): Double =
    val offset = PortableMath.hypot(shape.x - body.x, shape.y - body.y)
    shape match
      case _: Circle => offset
      case _ => offset + shape.boundingRadius

  /** Puts the body at fraction t of its motion. */
  private def place(body: Body, x0: Double, y0: Double, angle0: Double, dx: Double, dy: Double, dAngle: Double,
      t: Double): Unit =
    body.x = x0 + t * dx
    body.y = y0 + t * dy
    body.angle = angle0 + t * dAngle
    body.placeShapes()
