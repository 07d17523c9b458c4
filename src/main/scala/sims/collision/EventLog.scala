package sims.collision

import scala.collection.mutable.ArrayBuffer

/** The begin and end events of the last step, of one kind (contacts or sensors), as the world
  * shows them: filled by `next` and `show` at the end of each step into buffers reused from step
  * to step (no allocation but the events themselves), and kept one step back so that a failed
  * step can show the events of the step before again.
  */
private[sims] final class EventLog[B, E]:
  private var begins = ArrayBuffer.empty[B]
  private var ends = ArrayBuffer.empty[E]
  private var spareBegins = ArrayBuffer.empty[B]
  private var spareEnds = ArrayBuffer.empty[E]
  private var shown = false

  /** The begins shown: the last step's. */
  def shownBegins: collection.IndexedSeq[B] = begins

  /** The ends shown: the last step's. */
  def shownEnds: collection.IndexedSeq[E] = ends

  /** Starts a step: `undo` will go back to here. */
  def beginStep(): Unit = shown = false

  /** Empties the buffers the step's events go into, to be filled before `show`. */
  def next(): Unit =
    spareBegins.clear()
    spareEnds.clear()

  /** The buffer of this step's begins (after `next`). */
  def nextBegins: ArrayBuffer[B] = spareBegins

  /** The buffer of this step's ends (after `next`). */
  def nextEnds: ArrayBuffer[E] = spareEnds

  /** Shows this step's events. */
  def show(): Unit =
    swap()
    shown = true

  /** Shows the events of the step before again (the step under way failed after `show`). */
  def undo(): Unit =
    if shown then
      swap()
      shown = false

  /** Shows no events (the world was restored to a snapshot). */
  def clear(): Unit =
    begins.clear()
    ends.clear()

  private def swap(): Unit =
    val (b, e) = (begins, ends)
    begins = spareBegins; ends = spareEnds
    spareBegins = b; spareEnds = e
