package sims

import org.scalatest.Tag

/** Marks long simulations (many simulated seconds); the instrumented coverage run skips them. */
object SlowTest extends Tag("sims.SlowTest")
