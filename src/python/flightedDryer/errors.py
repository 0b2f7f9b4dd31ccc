"""errors: the kinds of failure every tool maps to its exit status.

  InputError      bad input: nothing was run (exit 2)
  RunError        a failed or non-converged run (exit 1)
  Diverged        a run stopped on a floating-point exception (a RunError)
  Busy            another run holds the folder (a RunError)
  SchedulerError  the scheduler refused or failed a request (exit 1)
"""


class InputError(Exception):
    """Bad input: nothing was run."""


class RunError(Exception):
    """A failed or non-converged run."""


class Diverged(RunError):
    """The solver stopped on a floating-point exception."""


class Busy(RunError):
    """Another run holds the folder."""


class SchedulerError(Exception):
    """The scheduler refused or failed a request."""
