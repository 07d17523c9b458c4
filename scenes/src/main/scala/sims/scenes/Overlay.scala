package sims.scenes

import sims.dynamics.Shape
import sims.geometry.{AABB, Segment, Vector2D}

/** What a scene shows besides its bodies and joints, for the renderer to draw over them: lines
  * (a laser's beam), shapes to highlight, boxes to mark (a query's region) and labels (a count).
  *
  * @param lines       segments in world coordinates
  * @param highlighted shapes drawn with a highlighted outline
  * @param boxes       boxes in world coordinates
  * @param labels      texts, each written with its lower-left corner at a point in world coordinates
  */
final case class Overlay(lines: Seq[Segment] = Nil, highlighted: Set[Shape] = Set.empty, boxes: Seq[AABB] = Nil,
    labels: Seq[(Vector2D, String)] = Nil)

/** The empty overlay. */
object Overlay:
  /** Nothing to draw. */
  val empty: Overlay = Overlay()
