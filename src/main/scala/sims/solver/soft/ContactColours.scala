package sims.solver.soft

/** The contacts of a step in colours: within a colour no two contacts share a body that moves
  * (fixed, kinematic and sleeping bodies do not count), so a colour's contacts can be solved in
  * any order, or at once on several workers, with the same result. The colours are solved in
  * turn, then the contacts that fit none (the overflow) one by one.
  *
  * Greedy and deterministic: each contact, in the table's order, takes the first colour that
  * neither of its moving bodies has yet. The order is the same for one worker or many, so the
  * number of workers never changes a bit of the result.
  */
private[sims] final class ContactColours:
  /** Contact indices, colour by colour, then the overflow. */
  var order: Array[Int] = new Array[Int](16)
  /** Colour k is `order(starts(k))` until `order(starts(k + 1))`; the overflow is from
    * `starts(ContactColours.Count)` to the number of active contacts.
    */
  val starts: Array[Int] = new Array[Int](ContactColours.Count + 1)
  // Per body: the colours it has (bit k for colour k); per contact: its colour.
  private var used: Array[Int] = new Array[Int](16)
  private var colourOf: Array[Int] = new Array[Int](16)
  private val counts: Array[Int] = new Array[Int](ContactColours.Count + 1)

  /** The number of contacts coloured by the last `colour`. */
  var size: Int = 0

  /** Colours the active contacts of `contacts` over `bodies`. */
  def colour(contacts: Contacts, bodies: SoftBodies): Unit =
    val n = contacts.active
    size = n
    if order.length < n then
      order = new Array[Int](math.max(n, 2 * order.length))
      colourOf = new Array[Int](order.length)
    if used.length < bodies.count then used = new Array[Int](math.max(bodies.count, 2 * used.length))
    java.util.Arrays.fill(used, 0, bodies.count, 0)
    java.util.Arrays.fill(counts, 0)
    val overflow = ContactColours.Count
    var c = 0
    while c < n do
      val a = contacts.bodyA(c)
      val b = contacts.bodyB(c)
      val movesA = bodies.moves(a)
      val movesB = bodies.moves(b)
      val taken = (if movesA then used(a) else 0) | (if movesB then used(b) else 0)
      // The lowest colour neither body has; past the last colour, the overflow.
      val colour = math.min(Integer.numberOfTrailingZeros(~taken), overflow)
      if colour < overflow then
        val bit = 1 << colour
        if movesA then used(a) |= bit
        if movesB then used(b) |= bit
      colourOf(c) = colour
      counts(colour) += 1
      c += 1
    var start = 0
    var k = 0
    while k <= overflow do
      starts(k) = start
      start += counts(k)
      counts(k) = starts(k) // from here: the next free slot of colour k
      k += 1
    c = 0
    while c < n do
      val colour = colourOf(c)
      order(counts(colour)) = c
      counts(colour) += 1
      c += 1

  /** The number of contacts in colour k (k = `ContactColours.Count`: the overflow). */
  def colourSize(k: Int): Int =
    if k < ContactColours.Count then starts(k + 1) - starts(k) else size - starts(k)

  override def toString: String =
    s"ContactColours(contacts = $size, sizes = ${(0 to ContactColours.Count).map(colourSize).mkString(", ")})"

private[sims] object ContactColours:
  /** The number of colours, as in Box2D v3; a contact that fits none goes to the overflow. */
  inline val Count = 24
