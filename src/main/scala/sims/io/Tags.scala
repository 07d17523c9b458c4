package sims.io

/** The tags of [[WorldCodec]]'s format: which kind of solver, shape or joint follows. */
private[io] object Tags:
  val ClassicSolver = 0
  val SoftSolver = 1
  val CircleShape = 0
  val RectangleShape = 1
  val RegularPolygonShape = 2
  val CapsuleShape = 3
  val EdgeShape = 4
  val HullPolygonShape = 5
  val ChainSegmentShape = 6
  val DistanceJointTag = 0
  val SpringJointTag = 1
  val RevoluteJointTag = 2
  val PrismaticJointTag = 3
  val MouseJointTag = 4
  val WeldJointTag = 5
  val WheelJointTag = 6
  val MotorJointTag = 7
