package sims.sweep

/** A run of a sweep threw: the message names its row, the cause is what it threw. */
final class RunFailedException(val row: Row, cause: Throwable)
    extends RuntimeException(s"run ${row.index} ($row) failed: $cause", cause)
