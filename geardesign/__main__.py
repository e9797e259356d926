"""``python -m geardesign`` and the ``geardesign`` console script."""

import sys


def entry() -> None:
    """Import the command line and run it; Ctrl-C while the modules load is one line too
    (:func:`geardesign.cli.main` handles it afterwards)."""
    try:
        from geardesign.cli import main
    except KeyboardInterrupt:
        sys.stderr.write("geardesign: interrupted\n")
        sys.exit(130)
    main()


if __name__ == "__main__":
    entry()
