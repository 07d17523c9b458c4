package sims.geometry

/** A 2x2 matrix `[[c11, c12], [c21, c22]]`, used to solve the 2x2 systems of point joints. */
final case class Matrix22(c11: Double, c12: Double, c21: Double, c22: Double):

  /** Matrix-vector product. */
  def *(v: Vector2D): Vector2D = Vector2D(c11 * v.x + c12 * v.y, c21 * v.x + c22 * v.y)

  /** Matrix sum. */
  def +(m: Matrix22): Matrix22 = Matrix22(c11 + m.c11, c12 + m.c12, c21 + m.c21, c22 + m.c22)

  /** Determinant. */
  def determinant: Double = c11 * c22 - c12 * c21

  /** Solves `this * x = b` for x; the null vector when the matrix is singular. */
  def solve(b: Vector2D): Vector2D =
    val det = determinant
    if det == 0 then Vector2D.Null
    else Vector2D((c22 * b.x - c12 * b.y) / det, (c11 * b.y - c21 * b.x) / det)

/** Constants of [[Matrix22]]. */
object Matrix22:
  /** The identity matrix. */
  val Identity: Matrix22 = Matrix22(1, 0, 0, 1)
