package sims

import org.scalacheck.Gen
import sims.geometry.Vector2D

/** ScalaCheck generators shared by the property tests. */
object Generators:
  /** A coordinate in [-range, range]. */
  def coordinate(range: Double = 100): Gen[Double] = Gen.choose(-range, range)

  /** A vector with components in [-range, range]. */
  def vector(range: Double = 100): Gen[Vector2D] =
    for x <- coordinate(range); y <- coordinate(range) yield Vector2D(x, y)

  /** A vector of length at least 1e-3. */
  def nonNullVector(range: Double = 100): Gen[Vector2D] = vector(range).suchThat(_.length > 1e-3)

  /** An angle in [-2 pi, 2 pi]. */
  val angle: Gen[Double] = Gen.choose(-2 * math.Pi, 2 * math.Pi)

/** Assertion helpers for vectors. */
object Close:
  /** True when the vectors differ by at most `tolerance` in each component. */
  def apply(a: Vector2D, b: Vector2D, tolerance: Double): Boolean =
    math.abs(a.x - b.x) <= tolerance && math.abs(a.y - b.y) <= tolerance
