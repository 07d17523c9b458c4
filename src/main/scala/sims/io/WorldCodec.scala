package sims.io

import sims.dynamics.World

/** Saves a world to bytes and loads it back: the loaded world steps to the same bits as the
  * original would have (a saved game, a checkpoint of a long run).
  *
  * The format is the library's own, small and versioned (docs/saving.md describes it): big-endian
  * binary, doubles as their exact IEEE 754 bits, in this order:
  *   1. the magic bytes "SIMS" and the format version (an Int, [[FormatVersion]]);
  *   2. settings: time step, iterations, gravity, the two flags, time, the grid detector's cell
  *      side and pair limit, the solver (ClassicStep, or SoftStep with all its parameters),
  *      `enableSleep`;
  *   3. bodies in order: each shape (Circle, Rectangle, RegularPolygon, Capsule, Edge,
  *      ChainSegment with its neighbours' ends, or HullPolygon with its arguments and material,
  *      collidable, placement, filter bits, sensor), the body's frame (mass, inertia, the
  *      shapes' offsets) and state (placement, velocities, force, torque, fixed, bullet,
  *      kinematic, damping, gravity scale, id, name, and sleep: `enableSleep`,
  *      `sleepThreshold`, awake, the time it has rested and its sleeping island); then each
  *      shape's transient shapes, by index;
  *   4. joints in order (Distance, Spring, Revolute, Prismatic, Mouse, Weld, Wheel, Motor):
  *      bodies by index, the anchors and body placements they were made from, their settings
  *      (limits, motor, spring), soft-step impulses, `collideConnected`, name and break limits;
  *   5. the soft step's contact table (the last step's contacts with their impulses), if the
  *      world has stepped with the soft step;
  *   6. the pairs of shapes touching and overlapping sensors (the open pairs of the contact and
  *      sensor events), by index, so that a loaded world reports no begin for a pair that
  *      already touched.
  * A world's own subclass (its `postStep`), user shape, joint, detector or solver types are not
  * saved: `save` names the type it cannot write.
  */
object WorldCodec:
  /** The version of the format `save` writes; `load` reads this one and every earlier one
    * (version 1 had no capsules, edges, hull polygons, filter bits or `collideConnected`;
    * version 2 no sensors, bullets or open event pairs; version 3 no broadphase settings of the
    * soft step's own: it used the detector's; version 4 no kinematic bodies, damping, gravity
    * scales, ids or names, no contact-event switches, no weld, wheel or motor joints, no chain
    * segments, no joint limits, motors, springs or break limits, and two impulses per revolute
    * or prismatic joint; version 5 no sleeping: every body awake; version 6 no contact's
    * turnless sides).
    */
  val FormatVersion: Int = 7

  /** The bytes of `world`'s state; fails with an IllegalArgumentException naming a type it cannot
    * save.
    */
  def save(world: World): Array[Byte] = WorldWriter.write(world)

  /** A new `World()` with the state in `bytes`; fails with an IllegalArgumentException if they are
    * not a saved world of this format version or an earlier one.
    */
  def load(bytes: Array[Byte]): World = load(bytes, World())

  /** Loads the state in `bytes` into `world`, which must be new (no bodies, no joints) and have
    * the default kind of detector: e.g. `load(bytes, new World { override def postStep() = ... })`.
    */
  def load(bytes: Array[Byte], world: World): World = WorldReader.read(bytes, world)

  /** The magic bytes that begin a saved world. */
  private[io] val Magic: Int = 0x53494d53 // "SIMS"
