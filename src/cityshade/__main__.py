"""``python -m cityshade`` is the same as the ``cityshade`` command."""
from cityshade.cli.main import main

if __name__ == "__main__":
    main()
