package sims.robustness

import sims.dynamics.World

/** An exact fingerprint of a world's dynamic state: every body double, bit for bit. */
object StateHash:
  def apply(world: World): Long =
    var h = 1125899906842597L
    def mix(d: Double): Unit = h = 31 * h + java.lang.Double.doubleToRawLongBits(d)
    for b <- world.bodies do
      mix(b.pos.x); mix(b.pos.y); mix(b.rotation)
      mix(b.linearVelocity.x); mix(b.linearVelocity.y); mix(b.angularVelocity)
    mix(world.time)
    h
