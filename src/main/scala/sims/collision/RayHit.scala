package sims.collision

import sims.dynamics.Shape
import sims.geometry.Vector2D

/** Where a ray cast from `from` towards `to` enters a shape (see `World.rayCast`).
  *
  * @param shape the shape hit
  * @param point where the ray enters it, world coordinates: from + fraction (to - from)
  * @param normal the unit normal of the shape's outline there (an edge's faces the ray's start)
  * @param fraction how far along the ray, from 0 (at `from`) to 1 (at `to`)
  */
final case class RayHit(shape: Shape, point: Vector2D, normal: Vector2D, fraction: Double)
