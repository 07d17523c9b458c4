package sims.collision

import sims.dynamics.Shape

/** A growable list of shape pairs kept in two arrays (no tuple per pair). */
private[collision] final class PairBuffer:
  private var firsts = new Array[Shape](64)
  private var seconds = new Array[Shape](64)
  private var count = 0

  def size: Int = count
  def first(i: Int): Shape = firsts(i)
  def second(i: Int): Shape = seconds(i)
  def clear(): Unit = count = 0

  def add(a: Shape, b: Shape): Unit =
    if count == firsts.length then
      firsts = java.util.Arrays.copyOf(firsts, count * 2)
      seconds = java.util.Arrays.copyOf(seconds, count * 2)
    firsts(count) = a
    seconds(count) = b
    count += 1
