"""``python -m cityshade`` is the same as the ``cityshade`` command (whose entry point is
:func:`run` too)."""
from cityshade.runtime.startup import install_start_handler


def run() -> None:
    """The console script: one line and status 130 for a Ctrl-C from the very start (the
    package's ``__init__`` has installed the start-up handler already when it was the first
    import; this call covers a caller that imported the package before)."""
    install_start_handler()
    from cityshade.cli.main import main

    main(own_process=True)


if __name__ == "__main__":
    run()
