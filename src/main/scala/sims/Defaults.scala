package sims

import sims.geometry.Vector2D

/** Every default of the library, in one place: what a new world, shape, detector, joint, prefab
  * or solver starts with, and the fixed tolerances of SiMS 1.2. Each is a named constant; the
  * classes take them from here (docs/architecture.md lists them).
  */
object Defaults:
  // ---- World

  /** Duration of one time step, s. */
  val TimeStep: Double = 1.0 / 60

  /** Velocity and position correction iterations of the classic step. */
  val Iterations: Int = 10

  /** Acceleration of gravity, m/s^2. */
  val Gravity: Vector2D = Vector2D(0, -9.81)

  /** Linear (m/s) and angular (rad/s) speeds below this become exactly 0 in the classic step's
    * phase 5.
    */
  val RestingSpeed: Double = 0.0001

  // ---- Shapes

  /** Coefficient of restitution of a new shape (a pair uses the product of its two shapes'). */
  val Restitution: Double = 0.7

  /** Density of a shape made without one, kg/m^2. */
  val Density: Double = 1

  /** Coefficient of friction of a new shape (a pair uses the product of its two shapes'). */
  val Friction: Double = 0.707

  /** Collision categories of a new shape: the first of 32 (one bit each). */
  val CategoryBits: Int = 1

  /** Categories a new shape collides with: all of them. */
  val MaskBits: Int = -1

  /** Collision group of a new shape: none (groups decide before categories and masks). */
  val GroupIndex: Int = 0

  /** Whether the two bodies of a new joint collide with each other: yes, as in SiMS 1.2
    * (Box2D's joints default to no).
    */
  val CollideConnected: Boolean = true

  // ---- Collision

  /** Side of a grid cell of the broadphase, m. */
  val GridSide: Double = 2

  /** Shapes covering more grid cells than this bypass the grid and meet every shape directly. */
  val LargeShapeCells: Long = 64

  /** The most candidate pairs the broadphase may find in one step (`GridDetector.maxPairs`):
    * a step with more fails at once with an error naming the limit, rather than running out of
    * memory (each pair keeps a few hundred bytes: one million is about 300 MB). Shapes spread
    * out have a few pairs each; thousands piled at one point have n^2 / 2.
    */
  val MaxCandidatePairs: Int = 1_000_000

  /** Overlap the classic contact's position correction tolerates, m (as in SiMS 1.2). */
  val ToleratedOverlap: Double = 0.01

  // ---- Mouse joint

  /** Natural frequency of a new mouse joint's spring, Hz. */
  val MouseFrequency: Double = 5.0

  /** Damping ratio of a new mouse joint's spring (1 is critical). */
  val MouseDampingRatio: Double = 0.7

  /** Damping of a dragged body's rotation, 1/s. */
  val MouseAngularDamping: Double = 1.0

  // ---- Prefabs

  /** Distance between neighbouring nodes of a net, m. */
  val NetSpacing: Double = 0.3

  /** Radius of a net's nodes, m. */
  val NetNodeRadius: Double = 0.05

  /** Density of a net's nodes, kg/m^2. */
  val NetDensity: Double = 10

  /** Panels of a pylon. */
  val PylonLevels: Int = 10

  /** Distance between a pylon's two columns, m. */
  val PylonWidth: Double = 1.0

  /** Height of one panel of a pylon, m. */
  val PylonLevelHeight: Double = 1.0

  /** Radius of a pylon's nodes, m. */
  val PylonNodeRadius: Double = 0.15

  /** Density of a pylon's nodes, kg/m^2. */
  val PylonDensity: Double = 10

  // ---- SoftStep

  /** Substeps per time step. */
  val Substeps: Int = 4

  /** Stiffness of contacts, Hz (used at most 0.25 / substep). */
  val ContactHertz: Double = 30

  /** Damping ratio of contacts. */
  val ContactDampingRatio: Double = 10

  /** Contacts with a fixed body are stiffer by this factor. */
  val StaticContactFactor: Double = 2

  /** Stiffness of rigid joints, Hz (used at most 0.25 / substep). */
  val JointHertz: Double = 60

  /** Damping ratio of rigid joints. */
  val JointDampingRatio: Double = 2

  /** The fastest that overlap is pushed apart, m/s. */
  val ContactSpeed: Double = 3

  /** Impacts slower than this do not bounce, m/s. */
  val RestitutionThreshold: Double = 1
  /** The most passes of the soft step's restitution stage. */
  val RestitutionIterations: Int = 20
  /** The soft step's restitution passes stop once no bouncing point's normal velocity is off
    * its target by more than this, m/s.
    */
  val RestitutionTolerance: Double = 1e-6

  /** Overlap tolerance of the soft narrowphase's choices, m. */
  val LinearSlop: Double = 0.005

  /** Distance at which contact points are made before shapes touch, m (4 linear slops). */
  val SpeculativeDistance: Double = 0.02

  /** A contact's manifold is kept while its bodies moved less than this relative to each other,
    * m (10 linear slops).
    */
  val ContactPersistence: Double = 0.05

  /** A contact whose load would press it deeper than this is made stiffer (up to 0.25 /
    * substep), m.
    */
  val ContactLoadDepth: Double = 0.002

  // ---- Sleeping (the soft step's; see docs/two-solvers.md, Sleeping)

  /** A body slower than this (its centre's speed, and its extent times its angular speed) is
    * resting, for sleeping, m/s.
    */
  val SleepThreshold: Double = 0.05

  /** An island of touching or jointed bodies falls asleep once every body in it has been
    * resting this long, s.
    */
  val TimeToSleep: Double = 0.5

  // ---- Contact events and bullets

  /** A pair of shapes that touched stays touching, for its contact events, while its shapes
    * are at most this far apart (hysteresis: a box resting on the ground that loses its contact
    * for a step, by a bounce of micrometres, does not end and begin again), m.
    */
  val ContactHysteresis: Double = 0.005

  /** A bullet stopped at a fixed shape by the continuous collision stage is left reaching this
    * far into it, so that the next step's narrowphase finds the contact, m (half the classic
    * step's `ToleratedOverlap`).
    */
  val BulletDepth: Double = 0.005

  /** The time of impact of a bullet is found to within this distance of `BulletDepth`, m. */
  val BulletTolerance: Double = 0.0005

  /** The most advancement steps of one time of impact search; a search that has not met the
    * shape by then stops where it is (never beyond the shape).
    */
  val BulletIterations: Int = 64
