package sims.collision

import sims.dynamics.World

/** Finds the collisions of a world (documentation 5.3). The world calls `detect()` once per
  * step before velocity correction, and `refresh()` in every position-correction iteration.
  */
abstract class Detector:
  /** The world whose collisions this detector finds. */
  def world: World

  /** The collisions found by the last `detect()` or `refresh()`. */
  def collisions: collection.IndexedSeq[Collision]

  /** Finds all collisions from the current positions (broadphase and narrowphase). */
  def detect(): Unit

  /** Recomputes the collisions from the current positions. The default redoes `detect()`;
    * a detector may instead rerun only the narrowphase on the pairs the last `detect()` found.
    */
  def refresh(): Unit = detect()
