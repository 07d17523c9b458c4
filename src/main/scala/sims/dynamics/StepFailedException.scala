package sims.dynamics

/** Thrown by `World.step()` when a stage of the step threw an exception that is not one of the
  * Java platform's own (a user's detection method or post-step hook threw an exception of its
  * own type): the world was restored to its state before the step, `stage` names the stage that
  * failed and the cause is the original exception. Exceptions of the Java platform's types keep
  * their type instead (see `World.step`).
  */
final class StepFailedException(val stage: String, message: String, cause: Throwable)
    extends RuntimeException(message, cause)
