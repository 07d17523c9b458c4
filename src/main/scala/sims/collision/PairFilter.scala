package sims.collision

import sims.dynamics.{Body, Shape}

/** Which pairs of shapes may collide at all (SiMS's broadphase rule, with the filters of
  * Box2D): shapes of different bodies, not both fixed or kinematic, both collidable, accepted by their
  * collision filters (`categoryBits`, `maskBits`, `groupIndex`), neither transient to the
  * other, and their bodies not joined by a joint whose `collideConnected` is false. The
  * broadphase applies it to every pair whose bounds overlap. Defaults accept every pair, as
  * SiMS 1.2 did. Sensor shapes never collide; which shapes a sensor sees is `sensorSees`.
  */
private[sims] object PairFilter:
  /** True if `a` and `b` may collide (their bounds are checked by the caller). */
  def accepts(a: Shape, b: Shape): Boolean =
    (a.body ne b.body) && a.collidable && b.collidable &&
      !a.sensor && !b.sensor &&
      !(a.body.immovable && b.body.immovable) &&
      filtersAccept(a, b) &&
      !jointSeparated(a.body, b.body) &&
      (a.transientShapes.isEmpty || !a.transientShapes.contains(b)) &&
      (b.transientShapes.isEmpty || !b.transientShapes.contains(a))

  /** True if the sensor shape `sensor` sees `visitor` when they overlap: the rules of `accepts`
    * with the sensor taking the place of a collidable shape, a visitor that is not a sensor
    * itself (sensors do not see each other, as in Box2D 3.1).
    */
  def sensorSees(sensor: Shape, visitor: Shape): Boolean =
    (sensor.body ne visitor.body) && sensor.collidable && visitor.collidable &&
      sensor.sensor && !visitor.sensor &&
      !(sensor.body.immovable && visitor.body.immovable) &&
      filtersAccept(sensor, visitor) &&
      !jointSeparated(sensor.body, visitor.body) &&
      (sensor.transientShapes.isEmpty || !sensor.transientShapes.contains(visitor)) &&
      (visitor.transientShapes.isEmpty || !visitor.transientShapes.contains(sensor))

  /** Box2D's filter rule: the same non-zero group decides (positive: always, negative: never);
    * otherwise each shape's mask must share a bit with the other's categories.
    */
  def filtersAccept(a: Shape, b: Shape): Boolean =
    if a.groupIndex == b.groupIndex && a.groupIndex != 0 then a.groupIndex > 0
    else (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0

  /** True if a joint in their world keeps the two bodies from colliding. The world keeps the
    * list on each body (usually empty), so this costs nothing for bodies without such joints.
    */
  def jointSeparated(a: Body, b: Body): Boolean =
    val partners = a.jointPartners
    (partners ne Nil) && partners.contains(b)
