package sims.collision

import scala.collection.mutable.ArrayBuffer
import sims.dynamics.Shape

/** The last step's begins and ends of a [[PairTracker]] as event objects, made when first read
  * after a step (a world whose events nobody reads makes none): what [[ContactEvents]] and
  * [[SensorEvents]] share. The lists are reused and refilled after the next step.
  *
  * @tparam B the kind of a begin event
  * @tparam E the kind of an end event
  */
private[sims] abstract class TrackedEvents[B, E](tracker: PairTracker):
  private val beginList = ArrayBuffer.empty[B]
  private val endList = ArrayBuffer.empty[E]
  // The tracker's generation the lists were made for.
  private var made = -1L

  /** The k-th begin of the last step, made from the tracker's arrays. */
  protected def makeBegin(k: Int): B

  /** The k-th end of the last step, made from the tracker's arrays. */
  protected def makeEnd(k: Int): E

  /** The begins of the last step, in key order. */
  protected final def beginsOfLastStep: collection.IndexedSeq[B] =
    make()
    beginList

  /** The ends of the last step, in key order. */
  protected final def endsOfLastStep: collection.IndexedSeq[E] =
    make()
    endList

  /** The open pairs (begun and not ended), in key order. */
  protected final def openPairs: IndexedSeq[(Shape, Shape)] =
    val pairs = tracker.openPairs()
    IndexedSeq.tabulate(pairs.keys.length)(i => (pairs.first(i), pairs.second(i)))

  private def make(): Unit =
    if made != tracker.generation then
      beginList.clear()
      endList.clear()
      var k = 0
      while k < tracker.begins do
        beginList += makeBegin(k)
        k += 1
      k = 0
      while k < tracker.ends do
        endList += makeEnd(k)
        k += 1
      made = tracker.generation

  /** The number of begins and ends of the last step, for `toString`. */
  protected final def counts: String = s"${tracker.begins} begins, ${tracker.ends} ends"
