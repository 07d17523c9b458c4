package sims.collision.narrowphase

/** The narrowphase's methods for the last few pairs of shape classes, searched by identity: a
  * scene has a handful of class pairs, looked up for every candidate pair, and a map's key would
  * be a new tuple each time. The oldest entry makes room for a new one.
  */
private[sims] final class RecentMethods(size: Int):
  private val classes1, classes2 = new Array[Class[?]](size)
  private val methods = new Array[Narrowphase.Resolved](size)
  private var next = 0

  /** The methods remembered for classes (c1, c2), or null. */
  def find(c1: Class[?], c2: Class[?]): Narrowphase.Resolved =
    var k = 0
    while k < size && !((classes1(k) eq c1) && (classes2(k) eq c2)) do k += 1
    if k < size then methods(k) else null

  /** Remembers `resolved` as the methods for classes (c1, c2). */
  def remember(c1: Class[?], c2: Class[?], resolved: Narrowphase.Resolved): Unit =
    classes1(next) = c1
    classes2(next) = c2
    methods(next) = resolved
    next = (next + 1) % size

  /** Forgets every entry (the methods' lists changed). */
  def clear(): Unit =
    java.util.Arrays.fill(classes1.asInstanceOf[Array[AnyRef]], null)
    java.util.Arrays.fill(classes2.asInstanceOf[Array[AnyRef]], null)
    java.util.Arrays.fill(methods.asInstanceOf[Array[AnyRef]], null)

  override def toString: String = s"RecentMethods(size = $size)"
