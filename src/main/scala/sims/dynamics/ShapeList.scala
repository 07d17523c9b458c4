package sims.dynamics

import scala.collection.mutable.ArrayBuffer

/** A world's shapes in the order they joined it, each numbered by its join order
  * (`Shape.worldIndex`, never reused). The array the stages read is made again only when it is
  * read after a change, and the shapes of bodies that left are dropped from the list then too
  * (they are marked by a `worldIndex` of -1), so adding or removing n bodies one by one costs
  * O(n), not O(n^2).
  */
private[dynamics] final class ShapeList:
  private val list = ArrayBuffer.empty[Shape]
  private var snapshot = Array.empty[Shape]
  private var changed = false
  // Whether `list` still holds shapes of bodies that left (worldIndex -1).
  private var leftBehind = false
  private var nextIndex = 0

  /** The shapes of a body joining the world, numbered. */
  def add(body: Body): Unit =
    // A body that left and comes back must not find its old entries still listed.
    dropLeftBehind()
    for s <- body.shapes do
      s.worldIndex = nextIndex
      nextIndex += 1
    list ++= body.shapes
    changed = true

  /** The shapes of a body leaving the world (dropped from the list when next read or added to). */
  def remove(body: Body): Unit =
    body.shapes.foreach(_.worldIndex = -1)
    leftBehind = true
    changed = true

  /** The shapes as an array (not to be modified): a new array after each change, so views of an
    * earlier one stay as they were.
    */
  def array: Array[Shape] =
    if changed then
      dropLeftBehind()
      snapshot = list.toArray
      changed = false
    snapshot

  private def dropLeftBehind(): Unit =
    if leftBehind then
      list.filterInPlace(_.worldIndex >= 0)
      leftBehind = false
