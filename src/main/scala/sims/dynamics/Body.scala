package sims.dynamics

import scala.collection.immutable.ArraySeq
import sims.geometry.{PortableMath, Vector2D}

/** A rigid body made of one or more shapes (documentation chapter 2).
  *
  * The body's position is its centre of mass. Mass, centre of mass and moment of inertia are
  * computed once from the shapes (and again only if a shape is moved before the body joins a
  * world), not summed on every access. A body starts with rotation 0 whatever its shapes'
  * rotations; each shape keeps its offset from the centre and its rotation relative to the body.
  */
final class Body(initialShapes: Shape*):
  /** The shapes of this body, in the order given. */
  val shapes: IndexedSeq[Shape] = ArraySeq.from(initialShapes)

  if shapes.isEmpty then throw IllegalArgumentException("a Body needs at least one shape")
  for (s, i) <- shapes.zipWithIndex do
    if s == null then throw IllegalArgumentException(s"shape $i of a Body is null")
    if s.body != null then throw IllegalArgumentException(s"shape $s already belongs to a body")
    if shapes.indexWhere(_ eq s) != i then throw IllegalArgumentException(s"shape $s is given twice")
  shapes.foreach(_._body = this)
  // The same shapes in an array, for the solver's loops.
  private val shapeArray: Array[Shape] = shapes.toArray

  // State as plain doubles: the solver reads and writes these without allocating.
  private[sims] var x, y: Double = 0 // centre of mass
  private[sims] var angle: Double = 0
  private[sims] var vx, vy, w: Double = 0
  private[sims] var fx, fy, tau: Double = 0
  /** 1 / mass, 0 when fixed. */
  private[sims] var invMass: Double = 0
  /** 1 / I, 0 when fixed. */
  private[sims] var invI: Double = 0

  // Mass and inertia of the shapes (whether fixed or not), and the shapes' placements in the
  // body's frame: computed once from the shapes; read and put back by `sims.io` as they are.
  private[sims] var freeMass, freeI: Double = 0
  // `mass` and `I` as they read, kept with the inverses (set by `updateInverseMass`, declared
  // before the constructor's call of it): the classic joints divide by them in every position
  // iteration, and a field costs less there than a test of two flags.
  private var massNow, inertiaNow = 0.0
  private var _fixed = false
  private[sims] val offsetX, offsetY, relativeAngle = new Array[Double](shapes.length)
  // True when every shape sits on the centre of mass: moving needs no trigonometry then.
  private[sims] var allCentred = true

  /** Counts the changes of the body's placement and of its inverse masses: whatever is
    * computed from them (the narrowphase's last result of a pair, a joint's geometry) is still
    * valid while the count is unchanged.
    */
  private[sims] var placements: Long = 0

  /** The largest distance from the centre of mass to a point of the body: how far a point of
    * it moves when it turns by an angle a is at most extent * a.
    */
  private[sims] var extent: Double = 0

  /** The index of this body in its world's bodies, or -1 outside a world. */
  private[sims] var index: Int = -1

  /** The world this body is in, or null. */
  private[sims] var world: World = null

  /** The bodies this one must not collide with: the other body of each joint in its world
    * whose `collideConnected` is false, once per such joint (kept by the joints as they join
    * and leave the world, so the pair filter reads a short list instead of every joint).
    */
  private[sims] var jointPartners: List[Body] = Nil

  /** Adds one entry for `other` to the bodies this one must not collide with. */
  private[sims] def addJointPartner(other: Body): Unit = jointPartners = other :: jointPartners

  /** Removes one entry for `other` (another joint between the two may keep them apart). */
  private[sims] def removeJointPartner(other: Body): Unit =
    val i = jointPartners.indexWhere(_ eq other)
    if i >= 0 then jointPartners = jointPartners.patch(i, Nil, 1)

  // An edge has no mass: it may only be part of a fixed body (see Edge). Found with an index,
  // not `exists`: in a Scala.js program without edges, Scala.js 1.20's full optimizer turns
  // `exists(_.isInstanceOf[Edge])` into a loop that never calls the iterator's `next()`.
  private val hasEdge =
    var k = 0
    while k < shapes.length && !shapes(k).isInstanceOf[Edge] do k += 1
    k < shapes.length

  shapesChanged()
  if hasEdge then fixed = true

  /** Recomputes mass, centre of mass, inertia and the shapes' offsets from their positions. */
  private[sims] def shapesChanged(): Unit =
    placements += 1
    var m, sx, sy = 0.0
    for s <- shapes do
      m += s.mass
      sx += s.x * s.mass
      sy += s.y * s.mass
    // Only edges have no mass: a body made of edges alone (always fixed) takes the middle of
    // their centres for its centre and skips the checks, which its zero mass would fail.
    val massless = m == 0 && hasEdge && shapes.forall(_.isInstanceOf[Edge])
    // Checked before anything changes: a user's shape may have any mass, and sums and
    // moments of finite shapes can still overflow.
    if !massless then Shape.requireDerived(describe, "mass", m)
    val centreX = if massless then shapes.map(_.x).sum / shapes.length else sx / m
    val centreY = if massless then shapes.map(_.y).sum / shapes.length else sy / m
    if !java.lang.Double.isFinite(centreX) || !java.lang.Double.isFinite(centreY) then
      throw IllegalArgumentException(s"$describe: its centre of mass would be ($centreX, $centreY), not finite")
    var inertia = 0.0
    for s <- shapes do
      val dx = s.x - centreX
      val dy = s.y - centreY
      inertia += s.I + s.mass * (dx * dx + dy * dy)
    if !massless then Shape.requireDerived(describe, "moment of inertia", inertia)
    x = centreX
    y = centreY
    extent = 0
    val c = PortableMath.cos(-angle)
    val sn = PortableMath.sin(-angle)
    allCentred = true
    for (s, i) <- shapes.zipWithIndex do
      val dx = s.x - x
      val dy = s.y - y
      extent = math.max(extent, math.sqrt(dx * dx + dy * dy) + s.boundingRadius)
      offsetX(i) = dx * c - dy * sn
      offsetY(i) = dx * sn + dy * c
      relativeAngle(i) = s.angle - angle
      if dx != 0 || dy != 0 then allCentred = false
    freeMass = m
    freeI = inertia
    updateInverseMass()

  /** Sets mass, I and their inverses from the shapes' mass and inertia and whether the body is
    * fixed or kinematic.
    */
  private[sims] def updateInverseMass(): Unit =
    val immovable = _fixed || _kinematic
    invMass = if immovable then 0 else 1 / freeMass
    invI = if immovable then 0 else 1 / freeI
    massNow = if immovable then Double.PositiveInfinity else freeMass
    inertiaNow = if immovable then Double.PositiveInfinity else freeI

  /** Places every shape from the body's centre and rotation. */
  private[sims] def placeShapes(): Unit =
    placements += 1
    if allCentred then
      var i = 0
      while i < shapeArray.length do
        shapeArray(i).place(x, y, angle + relativeAngle(i))
        i += 1
    else
      val c = PortableMath.cos(angle)
      val s = PortableMath.sin(angle)
      var i = 0
      while i < shapeArray.length do
        shapeArray(i).place(x + offsetX(i) * c - offsetY(i) * s, y + offsetX(i) * s + offsetY(i) * c,
          angle + relativeAngle(i))
        i += 1

  /** Computes the bounds its shapes cache now (see `Shape.refreshBounds`). */
  private[sims] def refreshShapeBounds(): Unit =
    var i = 0
    while i < shapeArray.length do
      shapeArray(i).refreshBounds()
      i += 1

  /** Moves and rotates the body by the given amounts (solver use: no checks, no allocation). */
  private[sims] def displace(dx: Double, dy: Double, dAngle: Double): Unit =
    if dx != 0 || dy != 0 || dAngle != 0 then
      x += dx
      y += dy
      angle += dAngle
      placeShapes()

  /** Adds the impulse (px, py) acting at offset (rx, ry) from the centre (solver use). */
  private[sims] def impulseAt(px: Double, py: Double, rx: Double, ry: Double): Unit =
    vx += px * invMass
    vy += py * invMass
    w += (rx * py - ry * px) * invI

  /** Adds the force (forceX, forceY) acting at offset (rx, ry) from the centre (solver use:
    * no checks, so a non-finite force reaches the world's guard instead of failing here).
    */
  private[sims] def forceAt(forceX: Double, forceY: Double, rx: Double, ry: Double): Unit =
    if !_fixed then
      fx += forceX
      fy += forceY
      tau += rx * forceY - ry * forceX

  // Sleeping (used by the soft step; see docs/two-solvers.md, Sleeping).
  private var _awake = true
  private var _enableSleep = true
  private var _sleepThreshold = sims.Defaults.SleepThreshold
  /** How long the body has been resting (slower than `sleepThreshold`), s. */
  private[sims] var sleepTime: Double = 0
  /** The sleeping island the body belongs to while asleep (bodies that fell asleep together,
    * and wake together), or -1 while awake.
    */
  private[sims] var sleepIsland: Long = -1
  /** A fixed body placed by the user since the last step: the bodies asleep on it wake. */
  private[sims] var movedByUser: Boolean = false

  /** Whether the body is awake (default true). A body falls asleep under the soft step with the
    * island of bodies it touches or is jointed to, once all of them have been slower than their
    * `sleepThreshold` for `Defaults.TimeToSleep`; a sleeping body is not moved by the step, and
    * costs (nearly) nothing, until something wakes its island: a contact with an awake body, a
    * joint to one, the user setting its velocity, position, a force or an impulse, or a body of
    * its island leaving the world. A fixed body is always awake. The classic step ignores sleep.
    */
  def isAwake: Boolean = _awake

  /** `true` wakes the body and its island; `false` puts the body to sleep at once, its
    * velocities set to 0 (it wakes again as above: next to an awake body, at the next step).
    */
  def isAwake_=(value: Boolean): Unit =
    if value then wake()
    else if !_fixed && _awake then
      _awake = false
      vx = 0; vy = 0; w = 0
      sleepIsland = if world != null then world.newSleepIsland() else Long.MaxValue // numbered when added

  /** Whether the body may fall asleep (default true; the world has its own switch,
    * `World.enableSleep`). Turning it off wakes the body.
    */
  def enableSleep: Boolean = _enableSleep

  /** Lets the body fall asleep or keeps it awake (waking it). */
  def enableSleep_=(value: Boolean): Unit =
    _enableSleep = value
    if !value then wake()

  /** The speed below which the body counts as resting, for sleeping, m/s (default
    * `Defaults.SleepThreshold`): its centre's speed and its `extent` times its angular speed.
    */
  def sleepThreshold: Double = _sleepThreshold

  /** Sets the resting speed; finite and at least 0 (0: the body never rests, never sleeps). */
  def sleepThreshold_=(value: Double): Unit =
    if !(value >= 0) || value.isInfinite then
      throw IllegalArgumentException(s"sleepThreshold must be finite and at least 0, got $value")
    _sleepThreshold = value

  /** Wakes the body and every body asleep in its island. */
  private[sims] def wake(): Unit =
    sleepTime = 0
    if !_awake then
      val island = sleepIsland
      _awake = true
      sleepIsland = -1
      if world != null && island >= 0 then world.wakeIsland(island)

  /** Wakes the body alone (its island is being woken by the world, body by body). */
  private[sims] def wakeAlone(): Unit =
    _awake = true
    sleepTime = 0
    sleepIsland = -1

  /** Puts the body to sleep in `island` (the soft step, for a resting island). */
  private[sims] def fallAsleep(island: Long): Unit =
    _awake = false
    sleepIsland = island
    vx = 0; vy = 0; w = 0

  /** Puts back a sleep state as saved (snapshots, save files). */
  private[sims] def restoreSleep(awake: Boolean, time: Double, island: Long): Unit =
    _awake = awake
    sleepTime = time
    sleepIsland = island

  /** A change the user made to the body: wakes it (and its island), or, for a fixed body, the
    * bodies asleep on it.
    */
  private def touchedByUser(): Unit =
    if _fixed then
      if world != null then
        movedByUser = true
        world.fixedBodyMoved()
    else wake()

  private var _bullet = false

  /** Whether this body is a bullet (default false): after each step, under either solver, its
    * motion over the step is swept against the fixed shapes near its path, and it is stopped
    * where it would first have entered one (continuous collision), so that however fast it is
    * it never passes through a fixed shape. Costs a sweep per bullet and step; other bodies and
    * other pairs are unchanged (see docs/events.md for what each step catches without it).
    */
  def bullet: Boolean = _bullet

  /** Makes the body a bullet or an ordinary body again, at any time. */
  def bullet_=(value: Boolean): Unit =
    if value != _bullet then
      _bullet = value
      if world != null then world.bulletChanged(value)

  /** Resulting force on the centre of mass, N. */
  def force: Vector2D = Vector2D(fx, fy)

  /** Sets the resulting force; must be finite. */
  def force_=(f: Vector2D): Unit =
    Vector2D.requireFinite("force", f)
    fx = f.x; fy = f.y
    if f.x != 0 || f.y != 0 then wake()

  /** Resulting torque about the centre of mass, N m. */
  def torque: Double = tau

  /** Sets the resulting torque; must be finite. */
  def torque_=(t: Double): Unit =
    tau = Vector2D.requireFinite("torque", t)
    if t != 0 then wake()

  /** Velocity of the centre of mass, m/s. */
  def linearVelocity: Vector2D = Vector2D(vx, vy)

  /** Sets the linear velocity; must be finite. */
  def linearVelocity_=(v: Vector2D): Unit =
    Vector2D.requireFinite("linearVelocity", v)
    vx = v.x; vy = v.y
    if v.x != 0 || v.y != 0 then wake()

  /** Angular velocity, rad/s, counter-clockwise. */
  def angularVelocity: Double = w

  /** Sets the angular velocity; must be finite. */
  def angularVelocity_=(value: Double): Unit =
    w = Vector2D.requireFinite("angularVelocity", value)
    if value != 0 then wake()

  /** Position of the centre of mass, world coordinates. */
  def pos: Vector2D = Vector2D(x, y)

  /** Moves the body (and all its shapes) so that its centre of mass is at `newPos`. */
  def pos_=(newPos: Vector2D): Unit =
    Vector2D.requireFinite("pos", newPos)
    x = newPos.x; y = newPos.y
    placeShapes()
    if world != null then world.shapesMoved()
    touchedByUser()

  /** Rotation in radians, counter-clockwise; 0 when the body was made. */
  def rotation: Double = angle

  /** Rotates the body (and its shapes) about its centre of mass to `newRotation`. */
  def rotation_=(newRotation: Double): Unit =
    angle = Vector2D.requireFinite("rotation", newRotation)
    placeShapes()
    if world != null then world.shapesMoved()
    touchedByUser()

  /** Mass in kg: the shapes' sum, or positive infinity when fixed or kinematic. */
  def mass: Double = massNow

  /** Moment of inertia about the centre of mass (parallel-axis sum), or infinity when fixed or
    * kinematic.
    */
  def I: Double = inertiaNow

  /** Whether the body is fixed (immovable by forces and impulses). */
  def fixed: Boolean = _fixed

  /** Fixes or frees the body; fixing it also sets both velocities to 0. A body with an
    * [[Edge]] cannot be freed.
    */
  def fixed_=(value: Boolean): Unit =
    if !value && hasEdge then
      throw IllegalArgumentException(s"fixed must stay true for a body with an Edge (edges have no mass), got false")
    placements += 1 // the inverse masses change: cached effective masses must be recomputed
    val changed = value != _fixed
    if changed then wake() // a body asleep wakes with its island
    _fixed = value
    if value then
      vx = 0; vy = 0; w = 0
      _kinematic = false
    updateInverseMass()
    // A body just fixed is a fixed body the user moved: what slept on it wakes.
    if changed && value then touchedByUser()

  private var _kinematic = false

  /** Whether the body is kinematic (default false): moved by its velocity alone, which only the
    * user sets; forces, gravity, contacts and joints never change it, and its mass is infinite to
    * every other body. It pushes the dynamic bodies in its way and carries those that rest on it
    * by friction (a moving platform). Two kinematic or fixed bodies never collide.
    */
  def kinematic: Boolean = _kinematic

  /** Makes the body kinematic (it keeps its velocities; it stops being fixed) or dynamic again.
    * A body with an [[Edge]] cannot be kinematic.
    */
  def kinematic_=(value: Boolean): Unit =
    if value && hasEdge then
      throw IllegalArgumentException(s"kinematic must stay false for a body with an Edge (edges have no mass), got true")
    if value != _kinematic then
      placements += 1
      _kinematic = value
      if value then _fixed = false
      updateInverseMass()

  /** Whether neither forces nor contacts move the body: it is fixed or kinematic. */
  private[sims] def immovable: Boolean = _fixed || _kinematic

  /** Whether the body is kinematic and moving: it wakes what it touches and keeps a step busy. */
  private[sims] def movesItself: Boolean = _kinematic && (vx != 0 || vy != 0 || w != 0)

  private var _linearDamping = 0.0
  private var _angularDamping = 0.0
  private var _gravityScale = 1.0

  /** How fast the body's linear velocity decays by itself, 1/s (default 0): each step of length
    * h scales it by 1 / (1 + h linearDamping), as air drag would.
    */
  def linearDamping: Double = _linearDamping

  /** Sets the linear damping; must be finite and at least 0. */
  def linearDamping_=(value: Double): Unit =
    _linearDamping = Shape.requireNonNegative("linearDamping", value)

  /** How fast the body's angular velocity decays by itself, 1/s (default 0), as `linearDamping`. */
  def angularDamping: Double = _angularDamping

  /** Sets the angular damping; must be finite and at least 0. */
  def angularDamping_=(value: Double): Unit =
    _angularDamping = Shape.requireNonNegative("angularDamping", value)

  /** The part of the world's gravity that acts on this body (default 1; 0 makes it float,
    * -1 fall upwards).
    */
  def gravityScale: Double = _gravityScale

  /** Sets the gravity scale; must be finite. */
  def gravityScale_=(value: Double): Unit =
    _gravityScale = Vector2D.requireFinite("gravityScale", value)

  /** Whether the body's velocities decay by themselves (a damping not 0). */
  private[sims] def damped: Boolean = _linearDamping != 0 || _angularDamping != 0

  /** Anything of the user's that belongs with this body (default None): never read by the library. */
  var userData: Option[Any] = None

  private var _name: Option[String] = None

  /** The body's name (default None), kept by save and load: `World.bodyNamed` finds it. */
  def name: Option[String] = _name

  /** Names the body (or takes its name away with None); a name must not be null. */
  def name_=(value: Option[String]): Unit =
    if value == null || value.exists(_ == null) then throw IllegalArgumentException("name must not be null, use None")
    _name = value

  /** The body's id in its world, -1 before it first joins one: given by the world when the body
    * joins it (0, 1, 2, ... in the order bodies joined, never reused), kept by save and load, so
    * that `World.bodyById` finds the same body in a loaded world.
    */
  def id: Int = _id

  private[sims] var _id: Int = -1

  /** Adds `f` to the force on the centre of mass; nothing happens when the body is fixed.
    * Fails, changing nothing, if `f` or the total force would not be finite.
    */
  def applyForce(f: Vector2D): Unit =
    Vector2D.requireFinite("force", f)
    if !_fixed then
      addForce(f, null, 0)
      wake()

  /** Applies `f` at `point` (world coordinates): changes force and torque. Fails, changing
    * nothing, if an argument, the torque about the centre or the totals would not be finite.
    */
  def applyForce(f: Vector2D, point: Vector2D): Unit =
    Vector2D.requireFinite("force", f)
    Vector2D.requireFinite("point", point)
    if !_fixed then
      addForce(f, point, (point.x - x) * f.y - (point.y - y) * f.x)
      wake()

  /** Adds force `f` and torque `t` (of `f` at `point`, or 0 with no point) after checking that
    * every sum stays finite, so that an overflow is reported here, where it is given, and not by
    * the next step.
    */
  private def addForce(f: Vector2D, point: Vector2D, t: Double): Unit =
    if !java.lang.Double.isFinite(t) then
      throw IllegalArgumentException(s"force $f at point $point has a torque of $t about the centre of mass $pos, not finite")
    val (newX, newY, newTorque) = (fx + f.x, fy + f.y, tau + t)
    if !java.lang.Double.isFinite(newX) || !java.lang.Double.isFinite(newY) then
      throw IllegalArgumentException(s"force $f would make the body's total force ($newX, $newY), not finite")
    if !java.lang.Double.isFinite(newTorque) then
      throw IllegalArgumentException(s"force $f at point $point would make the body's total torque $newTorque, not finite")
    fx = newX; fy = newY; tau = newTorque

  /** Applies the impulse `p` at the centre of mass: changes the linear velocity. Fails,
    * changing nothing, if the velocity would not be finite.
    */
  def applyImpulse(p: Vector2D): Unit =
    Vector2D.requireFinite("impulse", p)
    addImpulse(p, null, 0, 0)

  /** Applies the impulse `p` at `point` (world coordinates): changes both velocities. Fails,
    * changing nothing, if the velocities would not be finite.
    */
  def applyImpulse(p: Vector2D, point: Vector2D): Unit =
    Vector2D.requireFinite("impulse", p)
    Vector2D.requireFinite("point", point)
    addImpulse(p, point, point.x - x, point.y - y)

  /** `impulseAt` after checking that the velocities stay finite. */
  private def addImpulse(p: Vector2D, point: Vector2D, rx: Double, ry: Double): Unit =
    val (newX, newY) = (vx + p.x * invMass, vy + p.y * invMass)
    val newW = w + (rx * p.y - ry * p.x) * invI
    if !java.lang.Double.isFinite(newX) || !java.lang.Double.isFinite(newY) || !java.lang.Double.isFinite(newW) then
      val at = if point == null then "" else s" at point $point"
      throw IllegalArgumentException(
        s"impulse $p$at would make the body's velocities ($newX, $newY) and $newW rad/s, not finite")
    vx = newX; vy = newY; w = newW
    if !_fixed then wake()

  /** Velocity of the body's point at `point` (world coordinates): `v + w x r`. */
  def velocityOfPoint(point: Vector2D): Vector2D =
    Vector2D(vx - w * (point.y - y), vy + w * (point.x - x))

  /** True if `point` lies in one of the body's shapes. */
  def contains(point: Vector2D): Boolean = shapes.exists(_.contains(point))

  override def toString: String =
    val named = _name.fold("")(n => s"name = $n, ")
    val numbered = if _id >= 0 then s"id = ${_id}, " else ""
    s"Body($numbered${named}pos = $pos, shapes = ${shapes.mkString(", ")})"

  /** The body by its shapes, for errors about its mass (its position may not exist yet). */
  private def describe: String = s"Body(${shapes.mkString(", ")})"
