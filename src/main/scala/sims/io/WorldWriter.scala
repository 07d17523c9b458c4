package sims.io

import java.io.{ByteArrayOutputStream, DataOutputStream}
import sims.collision.{GridDetector, PairTracker}
import sims.dynamics.{Body, Capsule, ChainSegment, Circle, Edge, HullPolygon, Rectangle, RegularPolygon, Shape, World}
import sims.dynamics.joints.{
  DistanceJoint, Joint, JointLimits, JointMotor, JointOrigin, JointSpring, MotorJoint, MouseJoint, PrismaticJoint, RevoluteJoint,
  SpringJoint, WeldJoint, WheelJoint
}
import sims.solver.{ClassicStep, SoftStep}
import sims.solver.soft.{ContactTable, Contacts, SoftWorkspace}
import sims.solver.soft.joints.JointConstraint

/** Writes a world in [[WorldCodec]]'s format; the order of `write` is the format's. */
private[io] object WorldWriter:
  import Tags.*

  def write(world: World): Array[Byte] =
    val bytes = ByteArrayOutputStream()
    val out = DataOutputStream(bytes)
    out.writeInt(WorldCodec.Magic)
    out.writeInt(WorldCodec.FormatVersion)
    settings(out, world)
    val shapeIndex = world.shapes.zipWithIndex.toMap
    val bodyIndex = world.bodies.zipWithIndex.toMap
    out.writeInt(world.bodies.length)
    world.bodies.foreach(body(out, _))
    for s <- world.shapes do
      out.writeInt(s.transientShapes.size)
      // Sorted: the same world gives the same bytes, whatever the set's order.
      s.transientShapes.toSeq.map(t => shapeIndex.getOrElse(t, -1)).sorted.foreach(out.writeInt)
    out.writeInt(world.joints.length)
    world.joints.foreach(joint(out, world, _, bodyIndex))
    contacts(out, world, shapeIndex)
    openPairs(out, world.contactTracker.openPairs(), shapeIndex)
    openPairs(out, world.sensorTracker.openPairs(), shapeIndex)
    out.flush()
    bytes.toByteArray

  private def settings(out: DataOutputStream, world: World): Unit =
    out.writeDouble(world.timeStep)
    out.writeInt(world.iterations)
    out.writeDouble(world.gravity.x)
    out.writeDouble(world.gravity.y)
    out.writeBoolean(world.enableCollisionDetection)
    out.writeBoolean(world.enablePositionCorrection)
    out.writeDouble(world.time)
    world.detector match
      case grid: GridDetector =>
        out.writeDouble(grid.gridSide)
        out.writeInt(grid.maxPairs)
      case other => unsupported("detector", other)
    world.solver match
      case ClassicStep => out.writeByte(ClassicSolver)
      case soft: SoftStep =>
        out.writeByte(SoftSolver)
        out.writeInt(soft.substeps)
        for d <- Seq(soft.contactHertz, soft.contactDampingRatio, soft.staticContactFactor, soft.jointHertz,
            soft.jointDampingRatio, soft.contactSpeed, soft.restitutionThreshold, soft.linearSlop,
            soft.speculativeDistance, soft.contactPersistence, soft.contactLoadDepth) do out.writeDouble(d)
        out.writeBoolean(soft.directJoints)
        out.writeDouble(soft.gridSide)
        out.writeInt(soft.maxPairs)
      case other => unsupported("solver", other)
    out.writeBoolean(world.enableContactEvents)
    out.writeBoolean(world.enableSleep)

  private def body(out: DataOutputStream, b: Body): Unit =
    out.writeInt(b.shapes.length)
    for (s, i) <- b.shapes.zipWithIndex do
      shape(out, s)
      out.writeDouble(b.offsetX(i))
      out.writeDouble(b.offsetY(i))
      out.writeDouble(b.relativeAngle(i))
    for d <- Seq(b.freeMass, b.freeI, b.extent, b.x, b.y, b.angle, b.vx, b.vy, b.w, b.fx, b.fy, b.tau) do
      out.writeDouble(d)
    out.writeBoolean(b.allCentred)
    out.writeBoolean(b.fixed)
    out.writeBoolean(b.bullet)
    out.writeBoolean(b.kinematic)
    for d <- Seq(b.linearDamping, b.angularDamping, b.gravityScale) do out.writeDouble(d)
    out.writeInt(b.id)
    name(out, b.name)
    out.writeBoolean(b.enableSleep)
    out.writeDouble(b.sleepThreshold)
    out.writeBoolean(b.isAwake)
    out.writeDouble(b.sleepTime)
    out.writeLong(b.sleepIsland)

  private def shape(out: DataOutputStream, s: Shape): Unit =
    s match
      case c: Circle =>
        out.writeByte(CircleShape)
        out.writeDouble(c.radius)
      case r: Rectangle =>
        out.writeByte(RectangleShape)
        out.writeDouble(r.halfWidth)
        out.writeDouble(r.halfHeight)
      case p: RegularPolygon =>
        out.writeByte(RegularPolygonShape)
        out.writeInt(p.n)
        out.writeDouble(p.radius)
      case c: Capsule =>
        out.writeByte(CapsuleShape)
        out.writeDouble(c.halfLength)
        out.writeDouble(c.radius)
      case c: ChainSegment =>
        out.writeByte(ChainSegmentShape)
        for d <- Seq(c.start.x, c.start.y, c.end.x, c.end.y) do out.writeDouble(d)
        for ghost <- Seq(c.previous, c.next) do
          out.writeBoolean(ghost.isDefined)
          for g <- ghost do
            out.writeDouble(g.x)
            out.writeDouble(g.y)
      case e: Edge =>
        out.writeByte(EdgeShape)
        for d <- Seq(e.start.x, e.start.y, e.end.x, e.end.y) do out.writeDouble(d)
      case h: HullPolygon =>
        out.writeByte(HullPolygonShape)
        // The points it was made from: the hull is found from them again, to the same bits.
        out.writeInt(h.points.length)
        for p <- h.points do
          out.writeDouble(p.x)
          out.writeDouble(p.y)
      case other => unsupported("shape", other)
    for d <- Seq(s.density, s.restitution, s.friction, s.x, s.y, s.angle) do out.writeDouble(d)
    out.writeBoolean(s.collidable)
    out.writeInt(s.categoryBits)
    out.writeInt(s.maskBits)
    out.writeInt(s.groupIndex)
    out.writeBoolean(s.sensor)
    out.writeBoolean(s.enableContactEvents)

  /** An optional name: whether there is one, then its UTF-8 bytes. */
  private def name(out: DataOutputStream, name: Option[String]): Unit =
    out.writeBoolean(name.nonEmpty)
    name.foreach(out.writeUTF)

  /** A joint's optional limits, motor and spring: each whether it is there, then its numbers. */
  private def parts(out: DataOutputStream, limits: Option[JointLimits], motor: Option[JointMotor],
      spring: Option[JointSpring]): Unit =
    out.writeBoolean(limits.nonEmpty)
    limits.foreach { l => out.writeDouble(l.lower); out.writeDouble(l.upper) }
    out.writeBoolean(motor.nonEmpty)
    motor.foreach { m => out.writeDouble(m.speed); out.writeDouble(m.maxForce) }
    out.writeBoolean(spring.nonEmpty)
    spring.foreach { s => out.writeDouble(s.hertz); out.writeDouble(s.dampingRatio) }

  private def joint(out: DataOutputStream, world: World, j: Joint, bodyIndex: Map[Body, Int]): Unit =
    def origin(o: JointOrigin): Unit =
      for d <- Seq(o.anchor1.x, o.anchor1.y, o.anchor2.x, o.anchor2.y, o.x1, o.y1, o.angle1, o.x2, o.y2, o.angle2) do
        out.writeDouble(d)
    def nodes(tag: Int, o: JointOrigin): Unit =
      out.writeByte(tag)
      out.writeInt(bodyIndex(j.node1))
      out.writeInt(bodyIndex(j.node2))
      origin(o)
    j match
      case d: DistanceJoint => nodes(DistanceJointTag, d.origin)
      case s: SpringJoint =>
        nodes(SpringJointTag, s.origin)
        out.writeDouble(s.springConstant)
        out.writeDouble(s.initialLength)
        out.writeDouble(s.damping)
      case r: RevoluteJoint =>
        nodes(RevoluteJointTag, r.origin)
        parts(out, r.limits, r.motor, r.spring)
      case p: PrismaticJoint =>
        nodes(PrismaticJointTag, p.origin)
        parts(out, p.limits, p.motor, p.spring)
      case w: WeldJoint =>
        nodes(WeldJointTag, w.origin)
        for d <- Seq(w.linearHertz, w.angularHertz, w.dampingRatio) do out.writeDouble(d)
      case w: WheelJoint =>
        nodes(WheelJointTag, w.origin)
        out.writeDouble(w.initialAxis.x)
        out.writeDouble(w.initialAxis.y)
        parts(out, w.limits, w.motor, w.spring)
      case m: MotorJoint =>
        out.writeByte(MotorJointTag)
        out.writeInt(bodyIndex(m.node1))
        out.writeInt(bodyIndex(m.node2))
        for d <- Seq(m.targetOffset.x, m.targetOffset.y, m.targetAngle, m.maxForce, m.maxTorque, m.correctionFactor) do
          out.writeDouble(d)
      case m: MouseJoint =>
        out.writeByte(MouseJointTag)
        out.writeInt(bodyIndex(m.node2))
        origin(m.origin)
        for d <- Seq(m.maxForce, m.frequency, m.dampingRatio, m.angularDamping, m.target.x, m.target.y) do
          out.writeDouble(d)
      case other => unsupported("joint", other)
    val impulses = softWorkspace(world).map(_.joints.impulsesOf(j)).getOrElse(new Array[Double](JointConstraint.rowsOf(j)))
    out.writeInt(impulses.length)
    impulses.foreach(out.writeDouble)
    out.writeBoolean(j.collideConnected)
    name(out, j.name)
    out.writeDouble(j.breakForce)
    out.writeDouble(j.breakTorque)

  /** The soft step's committed contacts, if the world has stepped with the soft step. */
  private def contacts(out: DataOutputStream, world: World, shapeIndex: Map[Shape, Int]): Unit =
    softWorkspace(world).map(_.table.committed) match
      case None => out.writeBoolean(false)
      case Some(table) =>
        out.writeBoolean(true)
        // Contacts of shapes removed from the world since are never matched again: left out.
        val kept = (0 until table.count).filter(c =>
          shapeIndex.contains(table.shapeA(c)) && shapeIndex.contains(table.shapeB(c)))
        out.writeInt(kept.length)
        for c <- kept do
          out.writeInt(shapeIndex(table.shapeA(c)))
          out.writeInt(shapeIndex(table.shapeB(c)))
          out.writeInt(table.pointCount(c))
          out.writeInt(table.ids(2 * c))
          out.writeInt(if table.pointCount(c) > 1 then table.ids(2 * c + 1) else 0)
          out.writeInt(table.side(c))
          out.writeByte(table.turnless(c))
          ContactTable.saved(table, c).foreach(out.writeDouble)
          // A contact has room for two points (ids, cold block); the slots of a missing one hold
          // whatever an earlier contact left there, and so do the slots for keeping of a contact
          // never kept. Written as zeros: the same world, the same bytes.
          val used = ContactTable.ColdHeader + table.pointCount(c) * ContactTable.ColdPoint
          val uncached = table.side(c) == ContactTable.Uncached
          for k <- 0 until ContactTable.ColdStride do
            val written = k < used && !(uncached && ContactTable.cachedSlot(k))
            out.writeDouble(if written then table.cold(table.coldOffset(c) + k) else 0.0)

  /** The soft step's data of `world`, if it has stepped with the soft step. */
  private def softWorkspace(world: World): Option[SoftWorkspace] =
    world.carriedStates.collectFirst { case soft: SoftWorkspace => soft }

  /** Open event pairs, in key order, by shape index; pairs with a shape that has left the world
    * (which end at the next step) are left out, and their ends with them.
    */
  private def openPairs(out: DataOutputStream, pairs: PairTracker.Saved, shapeIndex: Map[Shape, Int]): Unit =
    val kept = pairs.keys.indices.filter(i => shapeIndex.contains(pairs.first(i)) && shapeIndex.contains(pairs.second(i)))
    out.writeInt(kept.length)
    for i <- kept do
      out.writeInt(shapeIndex(pairs.first(i)))
      out.writeInt(shapeIndex(pairs.second(i)))

  private def unsupported(what: String, value: AnyRef): Nothing =
    throw IllegalArgumentException(s"cannot save a $what of type ${value.getClass.getName}: the format " +
      s"knows the library's own kinds only")
