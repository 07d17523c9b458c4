package sims.collision

import sims.collision.broadphase.{KeptPairs, UniformGrid}
import sims.collision.narrowphase.Narrowphase
import sims.dynamics.Shape

/** A world's collision stages, one of each, shared by both steps and the queries: the
  * broadphase (the grid), the list of candidate pairs, and the narrowphase (the registry's
  * entries resolved for the shape classes of the world's pairs, with the classic step's objects).
  * Each user brings its own settings (the grid's cell side, the limit of pairs) to each use: the
  * classic step its detector's ([[GridDetector]]), the soft step its own, the queries the
  * detector's cell side.
  */
private[sims] final class CollisionPipeline:
  /** The broadphase: whoever uses it last (a step, or a query) has its shapes' bounds in it. */
  val broadphase: UniformGrid = UniformGrid()
  /** The candidate pairs of the last step. */
  val pairs: PairBuffer = PairBuffer()
  /** The narrowphase's resolution of shape classes to the registry's entries and the methods lists. */
  val narrowphase: Narrowphase = Narrowphase()

  /** Whether the broadphase holds every shape's exact bounds for the queries (set by them),
    * rather than a step's collidable shapes with its margins.
    */
  var holdsQueryBounds: Boolean = false

  /** Replaces the candidate pairs with those of `shapes` (world order), their bounds enlarged by
    * `margin` and by how far their bodies can move in `sweep` seconds, in cells of `gridSide`,
    * in the grid's coarse order (`inGridOrder`, SiMS's) or its own; fails past `maxPairs`
    * pairs, naming `limitName`, the setting that raises it.
    */
  def findPairs(shapes: Array[Shape], gridSide: Double, maxPairs: Int, limitName: String, margin: Double,
      sweep: Double, inGridOrder: Boolean): Unit =
    takeBounds(shapes, gridSide, maxPairs, limitName, margin, sweep)
    broadphase.findPairs(pairs, inGridOrder)

  /** The soft step's pairs kept from step to step (see [[KeptPairs]]). */
  val kept: KeptPairs = KeptPairs()

  // The kept pairs' full search on one thread.
  private val serialSearch: KeptPairs.Search = (grid, buffer) =>
    grid.endUpdate()
    grid.findPairs(buffer, inGridOrder = false)

  /** `findPairs` through the kept pairs of a world at `revision`, in their order: the grid
    * searches only when they no longer hold (see [[KeptPairs]]); the kept pairs may number up to
    * twice `maxPairs`.
    */
  def findKeptPairs(shapes: Array[Shape], gridSide: Double, maxPairs: Int, limitName: String, margin: Double,
      sweep: Double, revision: Long): Unit =
    takeSettings(gridSide, maxPairs, limitName)
    broadphase.beginUpdate(shapes, margin, sweep, everyShape = false)
    broadphase.boundsOf(0, shapes.length)
    kept.pairsOf(broadphase, revision, maxPairs, limitName, pairs, serialSearch)

  /** `findPairs` in the grid's own order, shared among threads: takes the settings as
    * `findPairs` does and starts the broadphase's update (see [[UniformGrid.beginUpdate]]); the
    * caller then runs the broadphase's shared stages in turn, each for ranges of the shapes at
    * once: `boundsOf`; `beginFineCells`, `fineCellsOf`, `endFineCells`; `beginSharedGrid` (if
    * true: `buildGridOf`, `linkGridOf`, `endSharedGrid`); then `findPairsOf`, each range into a
    * buffer of its own with this `maxPairs`, and `endShared(pairs, ...)`.
    */
  def beginSharedBounds(shapes: Array[Shape], gridSide: Double, maxPairs: Int, limitName: String, margin: Double,
      sweep: Double): Unit =
    takeSettings(gridSide, maxPairs, limitName)
    broadphase.beginUpdate(shapes, margin, sweep, everyShape = false)

  private def takeBounds(shapes: Array[Shape], gridSide: Double, maxPairs: Int, limitName: String, margin: Double,
      sweep: Double): Unit =
    takeSettings(gridSide, maxPairs, limitName)
    broadphase.update(shapes, margin, sweep, everyShape = false)

  private def takeSettings(gridSide: Double, maxPairs: Int, limitName: String): Unit =
    holdsQueryBounds = false
    broadphase.gridSide = gridSide
    pairs.limit = maxPairs
    pairs.limitName = limitName
    pairs.clear()
