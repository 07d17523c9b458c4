package sims.scenes

import sims.dynamics.Shape
import sims.geometry.{AABB, Segment}

/** What a scene shows besides its bodies and joints, for the renderer to draw over them: lines
  * (a laser's beam), shapes to highlight and boxes to mark (a query's region).
  *
  * @param lines       segments in world coordinates
  * @param highlighted shapes drawn with a highlighted outline
  * @param boxes       boxes in world coordinates
  */
final case class Overlay(lines: Seq[Segment] = Nil, highlighted: Set[Shape] = Set.empty, boxes: Seq[AABB] = Nil)

/** The empty overlay. */
object Overlay:
  /** Nothing to draw. */
  val empty: Overlay = Overlay()
