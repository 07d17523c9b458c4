package sims.collision

import org.scalacheck.Gen
import org.scalatest.funsuite.AnyFunSuite
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks
import sims.dynamics.{Body, Circle, Rectangle, World}
import sims.dynamics.joints.{DistanceJoint, RevoluteJoint}
import sims.geometry.Vector2D
import sims.solver.SoftStep

/** Collision filtering: Box2D's rule on categories, masks and groups, and joints whose bodies
  * do not collide, under both steps.
  */
class PairFilterSpec extends AnyFunSuite with Matchers with ScalaCheckPropertyChecks:

  private def filtered(category: Int, mask: Int, group: Int): Circle =
    val c = Circle(1, 1)
    c.categoryBits = category
    c.maskBits = mask
    c.groupIndex = group
    c

  test("the filter rule's truth table") {
    // (category, mask, group) of A and of B, and whether they may collide.
    val rows = Seq(
      ((1, -1, 0), (1, -1, 0), true), // defaults: everything collides, as in SiMS 1.2
      ((2, ~4, 0), (4, -1, 0), false), // A's mask lacks B's category
      ((2, -1, 0), (4, ~2, 0), false), // B's mask lacks A's category
      ((2, 4, 0), (4, 2, 0), true), // each mask holds the other's category
      ((2, 4, 0), (4, 1, 0), false), // one way is not enough
      ((0, -1, 0), (1, -1, 0), false), // no category: nothing collides with it
      ((2, 0, 3), (4, 0, 3), true), // the same positive group collides whatever the bits
      ((1, -1, -3), (1, -1, -3), false), // the same negative group never collides
      ((1, -1, 3), (1, -1, -3), true), // different groups: the bits decide
      ((2, ~4, -3), (4, -1, 5), false), // different groups: the bits decide
      ((1, -1, 7), (1, -1, 0), true), // one without a group: the bits decide
      ((2, 2, 0), (2, 2, 0), true)) // a category that collides with itself
    for (((ca, ma, ga), (cb, mb, gb), expected), row) <- rows.zipWithIndex do
      val a = filtered(ca, ma, ga)
      val b = filtered(cb, mb, gb)
      withClue(s"row $row: ") {
        PairFilter.filtersAccept(a, b) shouldBe expected
        PairFilter.filtersAccept(b, a) shouldBe expected
      }
  }

  test("property: the rule is symmetric and the defaults accept every filter that takes in category 1") {
    val bits = Gen.oneOf(Gen.choose(Int.MinValue, Int.MaxValue), Gen.oneOf(0, 1, 2, -1, ~1))
    val groups = Gen.choose(-2, 2)
    forAll(bits, bits, groups, bits, bits, groups) { (ca, ma, ga, cb, mb, gb) =>
      val a = filtered(ca, ma, ga)
      val b = filtered(cb, mb, gb)
      PairFilter.filtersAccept(a, b) shouldBe PairFilter.filtersAccept(b, a)
      val plain = Circle(1, 1)
      PairFilter.filtersAccept(plain, a) shouldBe ((ma & 1) != 0 && (ca != 0))
    }
  }

  /** Two overlapping balls and the candidate pairs the grid finds for them. */
  private def pairsOf(setUp: (Circle, Circle) => Unit): Int =
    val world = World()
    val a = Circle(0.5, 1)
    val b = Circle(0.5, 1); b.pos = Vector2D(0.5, 0)
    setUp(a, b)
    world += a.asBody
    world += b.asBody
    world.detector.detect()
    world.detector.asInstanceOf[GridDetector].candidatePairs.size

  test("the broadphase applies the filters") {
    pairsOf((_, _) => ()) shouldBe 1
    pairsOf { (a, b) => a.categoryBits = 2; b.maskBits = ~2 } shouldBe 0
    pairsOf { (a, b) => a.groupIndex = -1; b.groupIndex = -1 } shouldBe 0
    pairsOf { (a, b) => a.groupIndex = 1; b.groupIndex = 1; a.maskBits = 0 } shouldBe 1
  }

  /** Two overlapping boxes, the second joined to the first by `joint` when given. */
  private final class Pair(solverIsSoft: Boolean):
    val world = World()
    if solverIsSoft then world.solver = SoftStep()
    world.gravity = Vector2D.Null
    val first = Rectangle(0.5, 0.5, 1).asBody
    private val secondShape = Rectangle(0.5, 0.5, 1)
    secondShape.pos = Vector2D(0.8, 0)
    val second = secondShape.asBody
    world += first
    world += second

    /** Contacts of the two bodies after one step. */
    def contactsAfterStep(): Int =
      world.step()
      world.contacts.size

  for soft <- Seq(false, true) do
    val solver = if soft then "SoftStep" else "ClassicStep"

    test(s"$solver: a joint's bodies collide unless its collideConnected is false") {
      val pair = Pair(soft)
      val joint = RevoluteJoint(pair.first, pair.second, Vector2D(0.4, 0))
      joint.collideConnected shouldBe true
      pair.world += joint
      pair.contactsAfterStep() shouldBe 1 // the default: as in SiMS 1.2
      joint.collideConnected = false
      pair.contactsAfterStep() shouldBe 0
      joint.collideConnected = true
      pair.contactsAfterStep() shouldBe 1
    }

    test(s"$solver: filters keep overlapping shapes from colliding") {
      val pair = Pair(soft)
      pair.contactsAfterStep() shouldBe 1
      pair.first.shapes.head.groupIndex = -7
      pair.second.shapes.head.groupIndex = -7
      pair.contactsAfterStep() shouldBe 0
    }

  test("collideConnected set before joining, two joints between the same bodies, removal") {
    val pair = Pair(solverIsSoft = false)
    val hinge = RevoluteJoint(pair.first, pair.second, Vector2D(0.4, 0))
    hinge.collideConnected = false
    val rod = DistanceJoint(pair.first, pair.first.pos, pair.second, pair.second.pos)
    rod.collideConnected = false
    pair.world += hinge
    pair.world += rod
    pair.first.jointPartners shouldBe List(pair.second, pair.second)
    pair.contactsAfterStep() shouldBe 0
    pair.world -= hinge
    pair.contactsAfterStep() shouldBe 0 // the rod still keeps them apart
    pair.world -= rod
    pair.first.jointPartners shouldBe Nil
    pair.second.jointPartners shouldBe Nil
    pair.contactsAfterStep() shouldBe 1
    // A joint out of any world changes no body's list.
    rod.collideConnected = true
    rod.collideConnected = false
    pair.first.jointPartners shouldBe Nil
  }

  test("a joint may be in one world only") {
    val pair = Pair(solverIsSoft = false)
    val joint = RevoluteJoint(pair.first, pair.second, Vector2D(0.4, 0))
    pair.world += joint
    intercept[IllegalArgumentException](World() += joint).getMessage should include("another world")
    pair.world -= joint
    joint.world shouldBe null
  }
