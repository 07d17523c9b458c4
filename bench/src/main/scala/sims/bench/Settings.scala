package sims.bench

import sims.scenes.{BenchScenes, Scene, Scenes}

/** What the bench adds to its scenes: the engines' common settings and the scenes' lookup by
  * name. The scenes themselves are values of `sims.scenes` (`BenchScenes`): `ballpit-N`,
  * `pyramid-R` and `chain-N` are layouts that every engine translates as they are, and
  * `ballstack` is the examples' BallStack, in SiMS only.
  *
  * Every engine runs with 10 velocity and 10 position iterations (the scenes give gravity and
  * time step); every engine runs with sleeping off, the peers with continuous collision
  * detection off (SiMS has none for these scenes: no bullets).
  */
object Settings:
  /** Velocity and position iterations. */
  val Iterations: Int = 10
  /** Steps simulated before any measurement. */
  val WarmUpSteps: Int = 300

  /** The names of the scenes benchmarked: ballpit-N for each size, pyramid-20, chain-100, ballstack. */
  def names: Seq[String] = BenchScenes.names

  /** The scene with this name (a benchmark scene, or any other of `sims.scenes.Scenes.find`, in SiMS). */
  def scene(name: String): Scene =
    Scenes.find(name).getOrElse(throw IllegalArgumentException(s"unknown scene $name; the bench's: ${names.mkString(" ")}"))
