package sims.collision

import sims.dynamics.Shape

/** The key of a pair of shapes, the same for every table of pairs (contacts, events): the two
  * shapes' join orders (`worldIndex`, never reused), the first's in the high half. Keys sort in
  * the shapes' world order, so whatever is sorted by key is in a deterministic order.
  */
private[sims] object PairKey:
  /** The key of the pair (first, second). */
  def of(first: Shape, second: Shape): Long = (first.worldIndex.toLong << 32) | (second.worldIndex.toLong & 0xffffffffL)
