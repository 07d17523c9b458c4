package org.scalatestplus.scalacheck

import org.scalacheck.Gen
import org.scalacheck.rng.Seed
import org.scalatest.exceptions.{DiscardedEvaluationException, TestFailedException}
import org.scalatest.prop.{Configuration, Whenever}

/** The part of scalatestplus-scalacheck's `ScalaCheckPropertyChecks` that the shared tests use
  * (`forAll` over one to six generators with `minSuccessful`, and `whenever`), for Scala.js,
  * where that bridge is not published. Like the original, each check draws `minSuccessful`
  * cases with sizes growing over `sizeRange`, discards the cases that `whenever` or a
  * generator's filter rejects (up to `maxDiscardedFactor` times as many), and fails with the
  * drawn arguments; unlike it, it does not shrink them. Seeds are fixed, so runs repeat.
  */
trait ScalaCheckPropertyChecks extends Whenever with Configuration:

  /** Checks `fun` on values drawn from 1 generator. */
  def forAll[A](genA: Gen[A], configParams: PropertyCheckConfigParam*)(fun: A => Any): Unit =
    check(configParams, Seq(genA))((size, seeds) => fun(draw(genA, size, seeds)))

  /** Checks `fun` on values drawn from 2 generators. */
  def forAll[A, B](genA: Gen[A], genB: Gen[B], configParams: PropertyCheckConfigParam*)(fun: (A, B) => Any): Unit =
    check(configParams, Seq(genA, genB))((size, seeds) => fun(draw(genA, size, seeds), draw(genB, size, seeds)))

  /** Checks `fun` on values drawn from 3 generators. */
  def forAll[A, B, C](genA: Gen[A], genB: Gen[B], genC: Gen[C], configParams: PropertyCheckConfigParam*)(fun: (A, B, C) => Any): Unit =
    check(
      configParams, Seq(genA, genB, genC))((size, seeds) => fun(draw(genA, size, seeds), draw(genB, size, seeds), draw(genC, size, seeds)))

  /** Checks `fun` on values drawn from 4 generators. */
  def forAll[A, B, C, D](genA: Gen[A], genB: Gen[B], genC: Gen[C], genD: Gen[D], configParams: PropertyCheckConfigParam*)(fun: (A, B, C,
          D) => Any): Unit =
    check(configParams, Seq(genA, genB, genC, genD))((size, seeds) =>
      fun(draw(genA, size, seeds), draw(genB, size, seeds), draw(genC, size, seeds), draw(genD, size, seeds)))

  /** Checks `fun` on values drawn from 5 generators. */
  def forAll[A, B, C, D, E](genA: Gen[A], genB: Gen[B], genC: Gen[C], genD: Gen[D], genE: Gen[E], configParams: PropertyCheckConfigParam*)(
      fun: (A, B, C, D, E) => Any): Unit =
    check(configParams, Seq(genA, genB, genC, genD, genE))((size, seeds) =>
      fun(draw(genA, size, seeds), draw(genB, size, seeds), draw(genC, size, seeds), draw(genD, size, seeds), draw(genE, size, seeds)))

  /** Checks `fun` on values drawn from 6 generators. */
  def forAll[A, B, C, D, E, F](genA: Gen[A], genB: Gen[B], genC: Gen[C], genD: Gen[D], genE: Gen[E], genF: Gen[F],
      configParams: PropertyCheckConfigParam*)(fun: (A, B, C, D, E, F) => Any): Unit =
    check(configParams, Seq(genA, genB, genC, genD, genE, genF))((size, seeds) =>
      fun(draw(genA, size, seeds), draw(genB, size, seeds), draw(genC, size, seeds), draw(genD, size, seeds), draw(genE, size, seeds),
        draw(genF, size, seeds)))

  /** Draws one value of `gen` at `size`, or discards the case when the generator rejects it. */
  private def draw[T](gen: Gen[T], size: Int, seeds: Iterator[Seed]): T =
    gen(Gen.Parameters.default.withSize(size), seeds.next()).getOrElse(throw DiscardedEvaluationException())

  private def check(configParams: Seq[PropertyCheckConfigParam], gens: Seq[Gen[?]])(
      run: (Int, Iterator[Seed]) => Unit): Unit =
    val config = getParameter(configParams, generatorDrivenConfig)
    val wanted = config.minSuccessful
    val maxDiscarded = (config.maxDiscardedFactor * wanted).toInt
    var seed = Seed(20261121L)
    val seeds = Iterator.continually { val s = seed; seed = seed.next; s }
    var succeeded = 0
    var discarded = 0
    while succeeded < wanted do
      val size = config.minSize + (config.sizeRange * succeeded.toLong / math.max(wanted, 1)).toInt
      val start = seed
      try
        run(size, seeds)
        succeeded += 1
      catch
        case _: DiscardedEvaluationException =>
          discarded += 1
          if discarded > maxDiscarded then
            throw TestFailedException(s"gave up after $succeeded successful cases and $discarded discarded", 0)
        case failure: Throwable if !failure.isInstanceOf[VirtualMachineError] =>
          // Draw the failing case's arguments again (same seeds) to name them.
          val replay = Iterator.iterate(start)(_.next)
          val arguments = gens.map(g => g(Gen.Parameters.default.withSize(size), replay.next()))
          throw TestFailedException(s"property failed after $succeeded successful cases at " +
              s"arguments ${arguments.map(_.fold("(rejected)")(_.toString)).mkString(", ")}: ${failure.getMessage}",
            failure, 0)
