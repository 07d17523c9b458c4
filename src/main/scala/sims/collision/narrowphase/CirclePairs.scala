package sims.collision.narrowphase

import sims.collision.{CircleCollision, Collision, ShapeSeparation}
import sims.collision.manifold.{CircleManifold, Manifold}
import sims.dynamics.{Circle, Shape}
import sims.geometry.Reach

/** The circle's entries in the narrowphase registry: circle against circle. */
private[sims] object CirclePairs:
  /** This kind's entries. */
  val entries: Seq[PairFunctions] = Seq(CircleCircle)

  private object CircleCircle extends PairFunctions(PairKind.CircleCircle):
    def colliding(a: Shape, b: Shape): Boolean = CircleCollision.colliding(a.asInstanceOf[Circle], b.asInstanceOf[Circle])

    def collision(a: Shape, b: Shape): Collision = CircleCollision(a.asInstanceOf[Circle], b.asInstanceOf[Circle])

    def collide(slot: PairSlot, a: Shape, b: Shape, pool: CollisionPool): Collision =
      val c1 = a.asInstanceOf[Circle]
      val c2 = b.asInstanceOf[Circle]
      val squared = CircleCollision.centreDistanceSquared(c1, c2)
      if !Reach.within(squared, c1.radius + c2.radius) then null
      else if slot.circle == null then { slot.circle = CircleCollision(c1, c2); slot.circle }
      else { slot.circle.compute(c1, c2, math.sqrt(squared)); slot.circle }

    def manifold(a: Shape, b: Shape, lastSide: Int, speculativeDistance: Double, linearSlop: Double,
        out: Manifold): Unit =
      CircleManifold.collide(a.asInstanceOf[Circle], b.asInstanceOf[Circle], speculativeDistance, out)

    def separation(a: Shape, b: Shape, out: ShapeSeparation): Boolean =
      val ca = a.asInstanceOf[Circle]
      val cb = b.asInstanceOf[Circle]
      out.points(ca.x, ca.y, ca.radius, cb.x, cb.y, cb.radius)
