package sims.scenes

import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers

/** The test scenes are found by name; their exact contents are held by the golden hashes. */
class TestScenesSpec extends AnyFunSuite with Matchers:

  test("the golden scenes and the determinism scene are found by name, ignoring case") {
    Scenes.find("golden-ballpit-300") shouldBe Some(TestScenes.GoldenBallpit)
    Scenes.find("Golden-Pyramid-12") shouldBe Some(BoxPyramid(12)) // the benchmark's pyramid-12
    Scenes.find("golden-mixed") shouldBe Some(TestScenes.GoldenMixed)
    Scenes.find("determinism") shouldBe Some(TestScenes.Determinism(0 until 12))
    TestScenes.find("golden-nothing") shouldBe None
  }

  test("the determinism scene joins the world in one order whatever the order of creation") {
    val natural = TestScenes.Determinism(0 until 12).build().world
    val reversed = TestScenes.Determinism((0 until 12).reverse).build().world
    reversed.bodies.map(_.pos) shouldBe natural.bodies.map(_.pos)
    an[IllegalArgumentException] should be thrownBy TestScenes.Determinism(Seq(0, 1, 1))
  }

  test("every test scene builds and starts inside its region") {
    for (name, scene) <- TestScenes.golden do
      val world = scene.build().world
      withClue(name)(world.bodies.filterNot(_.fixed).forall(b => scene.region.contains(b.pos)) shouldBe true)
  }
