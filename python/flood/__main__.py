"""``python -m flood ARGS`` and the ``flood`` console script of ``pip install``: the flood
command itself (the same C++ as the CLI, linked into the module), so every option, message and
exit code is the one docs/CLI.md and docs/ERRORS.md describe."""
import os
import sys

from . import _flood


def main(argv=None) -> int:
    """Runs the flood command with ``argv`` (default: this process's arguments) and returns its
    exit code. It writes to the process's standard output and error directly."""
    args = sys.argv[1:] if argv is None else list(argv)
    # Usage messages name the program as the user typed it.
    prog = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "flood"
    if prog in ("__main__.py", "-m", "-c", ""):
        prog = "python -m flood"
    sys.stdout.flush()
    sys.stderr.flush()
    return _flood._cli([prog] + [str(a) for a in args])


if __name__ == "__main__":
    sys.exit(main())
