package sims.dynamics

import scala.collection.mutable.ArrayBuffer

/** The data a world keeps for the solvers it steps with: each solver's own (its scratch arrays,
  * its contact table), made the first time the world steps with a solver of that kind and kept
  * while the world lives, so that one solver value can step many worlds and switching solvers
  * back and forth keeps each one's data. What a solver hands from one step to the next
  * implements [[CarriedState]]: snapshots and failed steps put it back.
  */
trait SolverWorkspaces:
  private val workspaces = ArrayBuffer.empty[AnyRef]

  /** This world's data of one kind (`kind`, a class of the solver's), made by `create` the first
    * time it is asked for; for solvers.
    */
  def workspace[W <: AnyRef](kind: Class[W], create: => W): W =
    var i = 0
    while i < workspaces.length && !kind.isInstance(workspaces(i)) do i += 1
    if i < workspaces.length then workspaces(i).asInstanceOf[W]
    else
      val made = create
      if made == null || !kind.isInstance(made) then
        throw IllegalArgumentException(s"create must make a ${kind.getName}, made $made")
      workspaces += made
      made

  /** The solvers' data that steps hand on, in the order the world made them. */
  private[sims] def carriedStates: collection.IndexedSeq[CarriedState] =
    workspaces.collect { case c: CarriedState => c }

  /** Marks the start of a step in every carried state. */
  protected def beginCarriedStates(): Unit =
    var i = 0
    while i < workspaces.length do
      workspaces(i) match
        case c: CarriedState => c.beginStep()
        case _ => ()
      i += 1

  /** Undoes the failed step in every carried state. */
  protected def undoCarriedStates(): Unit =
    var i = 0
    while i < workspaces.length do
      workspaces(i) match
        case c: CarriedState => c.undoStep()
        case _ => ()
      i += 1
