package sims.dynamics

/** The part of a solver's per-world data (`World.workspace`) that one step hands to the next
  * (the soft step's contact table and its joints' impulses), so that snapshots and failed steps
  * can put it back: a restored world then replays to the same bits.
  */
trait CarriedState:
  /** A copy of the carried state, for a snapshot of the world. */
  def copyState(): AnyRef

  /** Puts back a copy made by `copyState` (null: the state of a world that never stepped with
    * this solver).
    */
  def restoreState(saved: AnyRef): Unit

  /** Marks the start of a step: `undoStep` will go back to here. Cheap (no copy). */
  def beginStep(): Unit

  /** Undoes what the step begun last changed (it failed). */
  def undoStep(): Unit
