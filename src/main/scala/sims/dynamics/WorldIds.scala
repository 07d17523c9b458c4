package sims.dynamics

import scala.collection.mutable

/** A world's bodies by id (`Body.id`): a body joining the world keeps the id it has unless it
  * has none or another body of the world has it; then it gets the next number, counted from 0
  * in the order bodies joined, never given twice (a loaded world's bodies keep their saved ids).
  */
private[dynamics] final class WorldIds:
  private val byId = mutable.HashMap.empty[Int, Body]
  private var next = 0

  /** Gives `body` its id in this world and records it. */
  def register(body: Body): Unit =
    if body._id < 0 || byId.contains(body._id) then
      body._id = next
      next += 1
    else next = math.max(next, body._id + 1)
    byId(body._id) = body

  /** Forgets `body` (it keeps its id). */
  def unregister(body: Body): Unit = byId.remove(body._id)

  /** The body with that id, if any. */
  def body(id: Int): Option[Body] = byId.get(id)
