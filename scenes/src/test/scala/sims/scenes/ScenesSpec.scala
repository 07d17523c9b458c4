package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import sims.dynamics.{Body, World}

/** Every scene builds and runs headless without NaN, its bodies inside its stated region. */
class ScenesSpec extends AnyFunSuite:
  /** Simulated seconds per scene. */
  private val Seconds = 5.0
  /** The pile is the one slow scene: it runs for less so the whole suite stays short. */
  private val SecondsOf: Map[String, Double] = Map(Pile.name -> 2.0)
  /** Scenes known to leave their region because of the solver, not the scene: their region
    * check is pending until the solver holds them (it then fails, asking to remove the entry).
    * NaN is still checked strictly for them.
    */
  private val KnownEscapes: Map[String, String] = Map(
    Pile.name -> ("under the pile's weight a few small shapes (2 to 6 of 2,100, triangles first) sink deeper " +
      "than their own size into the ground; the separating axis is then a side of the shape, position correction " +
      "pushes it sideways and down, and it falls through the 4 m thick ground"))

  /** The first body not finite, with a description, if any. */
  private def notFinite(world: World): Option[String] =
    world.bodies.iterator.zipWithIndex.collectFirst { case (b, i) if !finite(b) => s"body $i is not finite: $b" }

  /** The first free body outside `region`, with a description, if any (fixed bodies such as
    * the ground may reach beyond the region: they never move).
    */
  private def outside(world: World, region: Region): Option[String] =
    world.bodies.iterator.zipWithIndex.collectFirst {
      case (b, i) if !b.fixed && !region.contains(b.pos) => s"body $i left $region: at ${b.pos}"
    }

  private def problem(world: World, region: Region): Option[String] = notFinite(world).orElse(outside(world, region))

  private def finite(b: Body): Boolean =
    b.pos.isFinite && b.linearVelocity.isFinite && !b.rotation.isNaN && !b.rotation.isInfinite &&
      !b.angularVelocity.isNaN && !b.angularVelocity.isInfinite

  test("scene names are unique and found ignoring case"):
    assert(Scenes.all.map(_.name.toLowerCase).distinct.size == Scenes.all.size)
    for s <- Scenes.all do assert(Scenes.find(s.name.toUpperCase).contains(s))
    assert(Scenes.find("NoSuchScene").isEmpty)

  test("every build is a fresh world"):
    for s <- Scenes.all do
      val a = s.build().world
      val b = s.build().world
      assert(a ne b)
      assert(a.bodies.size == b.bodies.size && a.bodies.size > 0, s.name)
      assert(a.bodies.zip(b.bodies).forall((x, y) => x ne y), s.name)

  test("every scene starts inside its region and its view"):
    for s <- Scenes.all do
      val world = s.build().world
      assert(problem(world, s.region).isEmpty, s"${s.name}: ${problem(world, s.region)}")
      assert(s.region.width > 0 && s.view.width > 0)

  test("every scene's action runs and the world steps on afterwards"):
    val withAction = Scenes.all.filter(_.build().action.isDefined)
    assert(withAction.map(_.name).toSet == Set(Cannon.name, Wave.name, RagdollScene.name))
    for scene <- withAction do
      val staged = scene.build()
      for _ <- 1 to 10 do staged.world.step()
      val bodies = staged.world.bodies.size
      staged.action.get.run()
      for _ <- 1 to 30 do staged.world.step()
      assert(notFinite(staged.world).isEmpty, scene.name)
      assert(staged.world.bodies.size >= bodies, scene.name)

  /** Scenes whose region is checked under the soft step too; every scene runs under it without
    * NaN, but whether the others keep their regions is the soft step's own tests' concern.
    */
  private val SoftRegions: Set[Scene] = Set(Queries, Filtering, Shapes)

  for
    scene <- Scenes.all
    soft <- Seq(false, true)
  do
    val seconds = SecondsOf.getOrElse(scene.name, Seconds)
    val under = if soft then " under the soft step" else ""
    val inside = if soft && !SoftRegions(scene) then "" else s", its bodies inside ${scene.region}"
    test(s"${scene.name} runs $seconds s$under without NaN$inside"):
      val staged = scene.build()
      val world = staged.world
      if soft then world.solver = sims.solver.SoftStep()
      val steps = math.round(seconds / world.timeStep).toInt
      val start = System.nanoTime()
      var firstNaN: Option[String] = None
      var firstEscape: Option[String] = None
      var step = 0
      while step < steps && firstNaN.isEmpty do
        world.step()
        firstNaN = notFinite(world).map(p => f"t = ${world.time}%.3f s: $p")
        if firstEscape.isEmpty then firstEscape = outside(world, scene.region).map(p => f"t = ${world.time}%.3f s: $p")
        step += 1
      val millis = (System.nanoTime() - start) / 1e6
      info(f"${scene.name}: $step steps, ${millis / step}%.3f ms/step")
      assert(firstNaN.isEmpty, s"${scene.name}: ${firstNaN.getOrElse("")}")
      if soft && !SoftRegions(scene) then info(s"region under the soft step, not checked here: ${firstEscape.getOrElse("kept")}")
      else KnownEscapes.get(scene.name).filter(_ => !soft) match
        case Some(reason) =>
          info(s"known: $reason; first escape: ${firstEscape.getOrElse("none")}")
          pendingUntilFixed(assert(firstEscape.isEmpty))
        case None => assert(firstEscape.isEmpty, s"${scene.name}: ${firstEscape.getOrElse("")}")
