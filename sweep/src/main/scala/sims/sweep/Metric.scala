package sims.sweep

import sims.dynamics.World

/** A number measured from a run's world once it has stopped: a column of the result table.
  *
  * @param name the column's name
  * @param measure the measurement; a run whose measurement is not finite still has its row
  */
final case class Metric(name: String, measure: World => Double):
  Axis.requireName(name)

  override def toString: String = s"Metric($name)"
