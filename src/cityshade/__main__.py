"""``python -m cityshade`` is the same as the ``cityshade`` command (whose entry point is
:func:`run` too)."""
import os
import signal
import sys


def _interrupted_while_starting(signum, frame) -> None:
    # Ctrl-C before the command has installed its own handler (first thing in main()): the
    # imports are still running and nothing is written yet, so leave at once.
    sys.stderr.write("cityshade: interrupted\n")
    sys.stderr.flush()
    os._exit(130)


def run() -> None:
    """The console script: one line and status 130 for a Ctrl-C from the very start."""
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, _interrupted_while_starting)
    from cityshade.cli.main import main

    main()


if __name__ == "__main__":
    run()
