package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.collision.narrowphase.BuiltInMethods
import sims.dynamics.{Shape, World}

/** The default detector (documentation 5.3): a uniform-grid broadphase followed by a
  * narrowphase of partial functions that users can extend.
  *
  * Broadphase ([[sims.collision.broadphase.UniformGrid]]): each shape goes into every square
  * cell of side `gridSide` its AABB touches (cell = floor(coordinate / gridSide)); two shapes
  * are a candidate pair when they share a cell, their AABBs overlap and [[PairFilter]] accepts
  * them. Each unordered pair is reported once, the shape that joined the world first being the
  * pair's first shape.
  *
  * Narrowphase ([[sims.collision.narrowphase.Narrowphase]]): `detectionMethods` are tried in
  * order on (first, second) and the first defined one decides; if it says true, the first
  * defined `collisionMethods` entry makes the collision. The choice is resolved once per pair
  * of shape classes (so a method must be defined or not by the shapes' classes alone, as all
  * pattern matches on types are).
  */
class GridDetector(val world: World) extends Detector:
  // The world's broadphase, pairs and narrowphase, which the soft step and the queries share.
  private def stages = world.collisionPipeline
  private def pairs = stages.pairs
  private def narrowphase = stages.narrowphase
  private val found = ArrayBuffer.empty[Collision]
  private var _gridSide = sims.Defaults.GridSide
  private var _maxPairs = sims.Defaults.MaxCandidatePairs

  /** Side of a grid cell in m (default 2). */
  def gridSide: Double = _gridSide

  override def toString: String = s"GridDetector(gridSide = $gridSide, maxPairs = $maxPairs)"

  /** Sets the cell side; must be positive and finite. */
  def gridSide_=(side: Double): Unit = _gridSide = Shape.requirePositive("gridSide", side)

  /** The most candidate pairs a step may have (default [[sims.Defaults.MaxCandidatePairs]]); a
    * step with more fails, changing nothing, with an IllegalStateException naming this limit.
    */
  def maxPairs: Int = _maxPairs

  /** Sets the limit of candidate pairs per step; must be at least 1. */
  def maxPairs_=(limit: Int): Unit =
    if limit < 1 then throw IllegalArgumentException(s"maxPairs must be at least 1, got $limit")
    _maxPairs = limit

  /** Collision tests, tried in order; append methods for new shape types. */
  val detectionMethods: ArrayBuffer[PartialFunction[(Shape, Shape), Boolean]] =
    ArrayBuffer.from(BuiltInMethods.tests)

  /** Collision constructors, tried in order; append methods for new shape types. */
  val collisionMethods: ArrayBuffer[PartialFunction[(Shape, Shape), Collision]] =
    ArrayBuffer.from(BuiltInMethods.collisions)

  def collisions: collection.IndexedSeq[Collision] = found

  /** The candidate pairs of the last step's broadphase (this detector's last `detect()` under
    * the classic step): (first, second) shapes, in order.
    */
  def candidatePairs: IndexedSeq[(Shape, Shape)] =
    IndexedSeq.tabulate(pairs.size)(i => (pairs.first(i), pairs.second(i)))

  def detect(): Unit =
    stages.findPairs(world.shapeBuffer, _gridSide, _maxPairs, "GridDetector.maxPairs", margin = 0, sweep = 0,
      inGridOrder = true)
    refresh()

  /** Reruns the narrowphase on the pairs of the last `detect()` from the current positions (on
    * the soft step's, if it ran since: it fills the world's broadphase with its own).
    */
  override def refresh(): Unit =
    if !pairs.slotsFilled then
      pairs.fillSlots()
      narrowphase.update(detectionMethods, collisionMethods)
      resolvePairs()
    else if narrowphase.update(detectionMethods, collisionMethods) then resolvePairs()
    found.clear()
    var i = 0
    while i < pairs.size do
      val c = narrowphase.collide(pairs.slot(i))
      if c != null then found += c
      i += 1

  /** Looks up the narrowphase methods of every pair once, for all the reruns of this step, and
    * lets every slot give back the collision objects its pair does not use.
    */
  private def resolvePairs(): Unit =
    var i = 0
    while i < pairs.created do
      val slot = pairs.slot(i)
      if i < pairs.size then
        slot.methods = narrowphase.resolve(slot.first, slot.second)
        narrowphase.releaseUnused(slot, slot.methods.kind)
      else narrowphase.releaseUnused(slot, null)
      i += 1
