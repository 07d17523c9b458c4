package sims.scenes

import sims.dynamics.World

/** A hex fingerprint of a world's dynamic state: every body's position, rotation and
  * velocities in world order, bit for bit (64-bit FNV-1a over the doubles' bits). The same on
  * the JVM, on Node and in a browser, so that tests can compare a run on one with a run on
  * another (the playground shows it too).
  */
object StateFingerprint:
  private val Offset = 0xcbf29ce484222325L
  private val Prime = 0x100000001b3L

  /** The fingerprint of `world`'s bodies now, as 16 hex digits. */
  def apply(world: World): String =
    var h = Offset
    def mix(value: Double): Unit =
      val bits = java.lang.Double.doubleToRawLongBits(value)
      var k = 0
      while k < 64 do
        h = (h ^ ((bits >>> k) & 0xff)) * Prime
        k += 8
    for b <- world.bodies do
      mix(b.pos.x); mix(b.pos.y); mix(b.rotation)
      mix(b.linearVelocity.x); mix(b.linearVelocity.y); mix(b.angularVelocity)
    val hex = java.lang.Long.toHexString(h)
    "0" * (16 - hex.length) + hex
