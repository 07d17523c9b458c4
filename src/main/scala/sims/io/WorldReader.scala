package sims.io

import java.io.{ByteArrayInputStream, DataInputStream, EOFException}
import sims.collision.{GridDetector, PairKey, PairTracker}
import sims.dynamics.{Body, Capsule, ChainSegment, Circle, Edge, HullPolygon, Rectangle, RegularPolygon, Shape, World}
import sims.dynamics.joints.{
  DistanceJoint, Joint, JointLimits, JointMotor, JointSpring, MotorJoint, MouseJoint, PrismaticJoint, RevoluteJoint, SpringJoint, WeldJoint,
  WheelJoint
}
import sims.geometry.Vector2D
import sims.solver.{ClassicStep, SoftStep}
import sims.solver.soft.{ContactTable, Contacts, SoftWorkspace}
import sims.solver.soft.joints.JointConstraint

/** Reads a world written by [[WorldWriter]], in the same order. */
private[io] object WorldReader:
  import Tags.*

  // The sleep states read with the bodies, by body, until the joints are in.
  private type SleepStates = scala.collection.mutable.HashMap[Body, (Boolean, Double, Long)]

  def read(bytes: Array[Byte], world: World): World =
    val sleepStates: SleepStates = scala.collection.mutable.HashMap.empty
    if bytes == null then throw IllegalArgumentException("bytes must not be null")
    if world == null then throw IllegalArgumentException("world must not be null")
    if world.bodies.nonEmpty || world.joints.nonEmpty then
      throw IllegalArgumentException(s"a world is loaded into a new world, but this one has ${world.bodies.length} " +
        s"bodies and ${world.joints.length} joints")
    val in = DataInputStream(ByteArrayInputStream(bytes))
    try
      if in.readInt() != WorldCodec.Magic then throw IllegalArgumentException("these bytes are not a saved SiMS world")
      val version = in.readInt()
      if version < 1 || version > WorldCodec.FormatVersion then
        throw IllegalArgumentException(s"a saved world of format version $version; this library reads versions " +
          s"1 to ${WorldCodec.FormatVersion}")
      settings(in, world, version)
      val bodies = IndexedSeq.fill(in.readInt())(body(in, version, sleepStates))
      bodies.foreach(world += _)
      val shapes = world.shapes
      for s <- shapes do s.transientShapes = Seq.fill(in.readInt())(shapes(in.readInt())).toSet
      for _ <- 0 until in.readInt() do world += joint(in, world, bodies, version)
      for b <- bodies; (awake, time, island) <- sleepStates.remove(b) do b.restoreSleep(awake, time, island)
      // New islands are numbered after the saved ones.
      world.sleepIslands = bodies.map(_.sleepIsland).foldLeft(world.sleepIslands)(math.max)
      if in.readBoolean() then contacts(in, world, version)
      if version >= 3 then world.restoreEvents(openPairs(in, shapes), openPairs(in, shapes))
      if in.available() != 0 then throw IllegalArgumentException(s"${in.available()} bytes after the saved world")
      world
    catch
      case e: EOFException => throw IllegalArgumentException("the saved world is cut short", e)
      case e: IndexOutOfBoundsException => throw IllegalArgumentException("the saved world refers to a missing body or shape", e)

  private def settings(in: DataInputStream, world: World, version: Int): Unit =
    world.timeStep = in.readDouble()
    world.iterations = in.readInt()
    world.gravity = Vector2D(in.readDouble(), in.readDouble())
    world.enableCollisionDetection = in.readBoolean()
    world.enablePositionCorrection = in.readBoolean()
    world.time = in.readDouble()
    world.detector match
      case grid: GridDetector =>
        grid.gridSide = in.readDouble()
        grid.maxPairs = in.readInt()
      case other =>
        throw IllegalArgumentException(s"a world is loaded into a world with a GridDetector, not a ${other.getClass.getName}")
    world.solver = in.readByte() match
      case ClassicSolver => ClassicStep
      case SoftSolver =>
        val substeps = in.readInt()
        val d = Array.fill(11)(in.readDouble())
        val directJoints = in.readBoolean()
        // Version 4 gave the soft step its own broadphase settings; before, it used the detector's.
        val (gridSide, maxPairs) = world.detector match
          case grid: GridDetector if version < 4 => (grid.gridSide, grid.maxPairs)
          case _ => (in.readDouble(), in.readInt())
        SoftStep(substeps, d(0), d(1), d(2), d(3), d(4), d(5), d(6), d(7), d(8), d(9), d(10), directJoints, gridSide,
          maxPairs)
      case tag => throw IllegalArgumentException(s"unknown solver tag $tag in the saved world")
    if version >= 5 then world.enableContactEvents = in.readBoolean()
    // Version 6 added sleeping; an earlier world had every body awake and may sleep now.
    if version >= 6 then world.enableSleep = in.readBoolean()

  private def body(in: DataInputStream, version: Int, sleepStates: SleepStates): Body =
    val count = in.readInt()
    val shapes = new Array[Shape](count)
    val frame = new Array[Double](3 * count)
    val placements = new Array[Double](3 * count)
    for i <- 0 until count do
      val s = shape(in, version)
      shapes(i) = s
      placements(3 * i) = s.x; placements(3 * i + 1) = s.y; placements(3 * i + 2) = s.angle
      frame(3 * i) = in.readDouble(); frame(3 * i + 1) = in.readDouble(); frame(3 * i + 2) = in.readDouble()
      // Made at its offset from the centre: a body placed as far as 1e307 m would overflow the
      // sums of its centre of mass, which are not needed here.
      s.place(frame(3 * i), frame(3 * i + 1), frame(3 * i + 2))
    val b = Body(shapes*)
    for i <- 0 until count do shapes(i).place(placements(3 * i), placements(3 * i + 1), placements(3 * i + 2))
    // The body's frame as it was computed when it was made, not again from the shapes' current
    // placements (which would differ in the last bits).
    for i <- 0 until count do
      b.offsetX(i) = frame(3 * i); b.offsetY(i) = frame(3 * i + 1); b.relativeAngle(i) = frame(3 * i + 2)
    b.freeMass = in.readDouble(); b.freeI = in.readDouble(); b.extent = in.readDouble()
    b.x = in.readDouble(); b.y = in.readDouble(); b.angle = in.readDouble()
    val (vx, vy, w) = (in.readDouble(), in.readDouble(), in.readDouble())
    b.fx = in.readDouble(); b.fy = in.readDouble(); b.tau = in.readDouble()
    b.allCentred = in.readBoolean()
    b.fixed = in.readBoolean()
    if version >= 3 then b.bullet = in.readBoolean()
    if version >= 5 then
      b.kinematic = in.readBoolean()
      b.linearDamping = in.readDouble()
      b.angularDamping = in.readDouble()
      b.gravityScale = in.readDouble()
      b._id = in.readInt()
      b.name = name(in)
    if version >= 6 then
      b.enableSleep = in.readBoolean()
      b.sleepThreshold = in.readDouble()
      val awake = in.readBoolean()
      val time = in.readDouble()
      // Put back once the joints are in (adding a joint wakes its bodies).
      sleepStates(b) = (awake, time, in.readLong())
    b.updateInverseMass()
    b.vx = vx; b.vy = vy; b.w = w
    b

  /** A shape; version 1 knew circles, rectangles and regular polygons only, and no filter bits. */
  private def shape(in: DataInputStream, version: Int): Shape =
    val s = in.readByte() match
      case CircleShape =>
        val radius = in.readDouble()
        Circle(radius, in.readDouble())
      case RectangleShape =>
        val (halfWidth, halfHeight) = (in.readDouble(), in.readDouble())
        Rectangle(halfWidth, halfHeight, in.readDouble())
      case RegularPolygonShape =>
        val (n, radius) = (in.readInt(), in.readDouble())
        RegularPolygon(n, radius, in.readDouble())
      case CapsuleShape if version >= 2 =>
        val (halfLength, radius) = (in.readDouble(), in.readDouble())
        Capsule(halfLength, radius, in.readDouble())
      case EdgeShape if version >= 2 =>
        val edge = Edge(Vector2D(in.readDouble(), in.readDouble()), Vector2D(in.readDouble(), in.readDouble()))
        in.readDouble() // its density, always 0
        edge
      case ChainSegmentShape if version >= 5 =>
        val (start, end) = (Vector2D(in.readDouble(), in.readDouble()), Vector2D(in.readDouble(), in.readDouble()))
        def ghost(): Option[Vector2D] = if in.readBoolean() then Some(Vector2D(in.readDouble(), in.readDouble())) else None
        val previous = ghost()
        val segment = ChainSegment(start, end, previous, ghost())
        in.readDouble() // its density, always 0
        segment
      case HullPolygonShape if version >= 2 =>
        val points = IndexedSeq.fill(in.readInt())(Vector2D(in.readDouble(), in.readDouble()))
        HullPolygon(points, in.readDouble())
      case tag => throw IllegalArgumentException(s"unknown shape tag $tag in the saved world")
    s.restitution = in.readDouble()
    s.friction = in.readDouble()
    s.place(in.readDouble(), in.readDouble(), in.readDouble())
    s.collidable = in.readBoolean()
    if version >= 2 then
      s.categoryBits = in.readInt()
      s.maskBits = in.readInt()
      s.groupIndex = in.readInt()
    if version >= 3 then s.sensor = in.readBoolean()
    if version >= 5 then s.enableContactEvents = in.readBoolean()
    s

  private def name(in: DataInputStream): Option[String] = if in.readBoolean() then Some(in.readUTF()) else None

  /** A joint's limits, motor and spring as `WorldWriter.parts` wrote them. */
  private def parts(in: DataInputStream): (Option[JointLimits], Option[JointMotor], Option[JointSpring]) =
    val limits = if in.readBoolean() then { val lower = in.readDouble(); Some(JointLimits(lower, in.readDouble())) }
    else None
    val motor = if in.readBoolean() then { val speed = in.readDouble(); Some(JointMotor(speed, in.readDouble())) }
    else None
    val spring = if in.readBoolean() then { val hertz = in.readDouble(); Some(JointSpring(hertz, in.readDouble())) }
    else None
    (limits, motor, spring)

  private def joint(in: DataInputStream, world: World, bodies: IndexedSeq[Body], version: Int): Joint =
    val tag = in.readByte()
    val node1 = if tag == MouseJointTag then null else bodies(in.readInt())
    val node2 = bodies(in.readInt())
    if tag == MotorJointTag then return finish(in, world, motorJoint(in, node1, node2), version)
    val anchor1 = Vector2D(in.readDouble(), in.readDouble())
    val anchor2 = Vector2D(in.readDouble(), in.readDouble())
    val placement = Array.fill(6)(in.readDouble())
    // The joint is made again with its bodies where they were when it was first made: its
    // anchors then have the same offsets and rotations to the bit.
    def atOrigin[J](make: => J): J =
      val saved = Array(node2.x, node2.y, node2.angle) ++
        (if node1 == null then Array.empty[Double] else Array(node1.x, node1.y, node1.angle))
      if node1 != null then { node1.x = placement(0); node1.y = placement(1); node1.angle = placement(2) }
      node2.x = placement(3); node2.y = placement(4); node2.angle = placement(5)
      try make
      finally
        node2.x = saved(0); node2.y = saved(1); node2.angle = saved(2)
        if node1 != null then { node1.x = saved(3); node1.y = saved(4); node1.angle = saved(5) }
    val j: Joint = tag match
      case DistanceJointTag => atOrigin(DistanceJoint(node1, anchor1, node2, anchor2))
      case SpringJointTag =>
        val (k, length, damping) = (in.readDouble(), in.readDouble(), in.readDouble())
        val spring = atOrigin(SpringJoint(node1, anchor1, node2, anchor2, k, length))
        spring.damping = damping
        spring
      case RevoluteJointTag =>
        val revolute = atOrigin(RevoluteJoint(node1, node2, anchor1))
        if version >= 5 then
          val (limits, motor, spring) = parts(in)
          revolute.limits = limits; revolute.motor = motor; revolute.spring = spring
        revolute
      case PrismaticJointTag =>
        val prismatic = atOrigin(PrismaticJoint(node1, anchor1, node2, anchor2))
        if version >= 5 then
          val (limits, motor, spring) = parts(in)
          prismatic.limits = limits; prismatic.motor = motor; prismatic.spring = spring
        prismatic
      case WeldJointTag if version >= 5 =>
        val (linearHertz, angularHertz, dampingRatio) = (in.readDouble(), in.readDouble(), in.readDouble())
        atOrigin(WeldJoint(node1, node2, anchor1, linearHertz, angularHertz, dampingRatio))
      case WheelJointTag if version >= 5 =>
        val axis = Vector2D(in.readDouble(), in.readDouble())
        val wheel = atOrigin(WheelJoint(node1, node2, anchor1, axis))
        val (limits, motor, spring) = parts(in)
        wheel.limits = limits; wheel.motor = motor; wheel.spring = spring
        wheel
      case MouseJointTag =>
        val maxForce = in.readDouble()
        val mouse = atOrigin(MouseJoint(node2, anchor1, maxForce))
        mouse.frequency = in.readDouble()
        mouse.dampingRatio = in.readDouble()
        mouse.angularDamping = in.readDouble()
        mouse.target = Vector2D(in.readDouble(), in.readDouble())
        mouse
      case other => throw IllegalArgumentException(s"unknown joint tag $other in the saved world")
    finish(in, world, j, version)

  /** A motor joint: its target, limits and correction (it has no anchors). */
  private def motorJoint(in: DataInputStream, node1: Body, node2: Body): MotorJoint =
    val d = Array.fill(6)(in.readDouble())
    MotorJoint(node1, node2, Some(Vector2D(d(0), d(1))), Some(d(2)), d(3), d(4), d(5))

  /** What every joint has after its own settings: the soft step's impulses, `collideConnected`,
    * and since version 5 its name and break limits.
    */
  private def finish(in: DataInputStream, world: World, j: Joint, version: Int): Joint =
    val count = in.readInt()
    val rows = JointConstraint.rowsOf(j)
    // Before version 5 revolute and prismatic joints had their two rows only (no limits, motor
    // or spring): the others' impulses are 0.
    val padded = version < 5 && count == 2 && (j.isInstanceOf[RevoluteJoint] || j.isInstanceOf[PrismaticJoint])
    if count != rows && !padded then
      throw IllegalArgumentException(s"$j carries $rows impulses, the saved world has $count")
    val impulses = new Array[Double](rows)
    for i <- 0 until count do impulses(i) = in.readDouble()
    // Only a world that stepped with the soft step has impulses; others get no soft step's data.
    if impulses.exists(_ != 0) then world.workspace(classOf[SoftWorkspace], SoftWorkspace()).joints.setImpulses(j, impulses)
    if version >= 2 then j.collideConnected = in.readBoolean()
    if version >= 5 then
      j.name = name(in)
      val breakForce = in.readDouble()
      val breakTorque = in.readDouble()
      j.breakForce = breakForce
      j.breakTorque = breakTorque
    j

  /** Open event pairs by shape index, keyed by the loaded shapes (whose join orders keep the
    * saved ones' order, so the keys stay sorted).
    */
  private def openPairs(in: DataInputStream, shapes: IndexedSeq[Shape]): PairTracker.Saved =
    val count = in.readInt()
    if count < 0 then throw IllegalArgumentException(s"a negative count of open pairs, $count, in the saved world")
    val first = new Array[Shape](count)
    val second = new Array[Shape](count)
    for i <- 0 until count do
      first(i) = shapes(in.readInt())
      second(i) = shapes(in.readInt())
    PairTracker.Saved(Array.tabulate(count)(i => PairKey.of(first(i), second(i))), first, second)

  /** The soft step's committed contacts, keyed by the loaded shapes. */
  private def contacts(in: DataInputStream, world: World, version: Int): Unit =
    val shapes = world.shapes
    val table = Contacts()
    // Saved by any detector: one of the user's may have listed a pair twice.
    table.pairsRepeat = true
    for _ <- 0 until in.readInt() do
      val (a, b) = (shapes(in.readInt()), shapes(in.readInt()))
      val c = table.add(in.readInt())
      table.shapeA(c) = a
      table.shapeB(c) = b
      table.bodyA(c) = a.body.index
      table.bodyB(c) = b.body.index
      table.keys(c) = PairKey.of(a, b)
      table.reportsEvents(c) = a.enableContactEvents && b.enableContactEvents
      table.ids(2 * c) = in.readInt()
      table.ids(2 * c + 1) = in.readInt()
      table.side(c) = in.readInt()
      // Before version 7 every contact's separation followed the general rule: no side turnless.
      table.turnless(c) = if version >= 7 then in.readByte() else 0
      if table.turnless(c) < 0 || table.turnless(c) > ContactTable.Turnless then
        throw IllegalArgumentException(s"a contact's turnless sides, ${table.turnless(c)}, are not 0 to 3 in the saved world")
      // Before version 5 a point's block had no ImpactGap (its last slot): it stays 0.
      ContactTable.load(table, c, () => in.readDouble(), ContactTable.savedPoint(version))
      for k <- 0 until ContactTable.ColdStride do table.cold(table.coldOffset(c) + k) = in.readDouble()
    world.workspace(classOf[SoftWorkspace], SoftWorkspace()).table.restoreCommitted(table)
