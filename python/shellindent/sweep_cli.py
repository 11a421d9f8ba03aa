"""`shellindent sweep STUDY --scheduler ADDRESS`: the CLI runs this module (app/dask_sweep.cpp)
to put a study's cases on an existing Dask cluster through shellindent.sweep().

    python3 -m shellindent.sweep_cli ADDRESS STUDY --out DIR [--quick] [--timeout SECONDS]

Prints the table (sweep.csv) to stdout and the progress to stderr as `shellindent sweep` does.
Exit codes as the CLI's: 0 every case finished, 1 a case failed or Ctrl-C, 2 bad input, which
includes a missing dask.distributed and a scheduler that does not answer within the timeout
(the message names --scheduler).
"""

import argparse
import sys

from .errors import InputError
from .sweep import sweep


def _error(address, reason):
    print(f"shellindent: error: command line: --scheduler = '{address}': {reason}",
          file=sys.stderr)
    return 2


def main(argv=None):
    parser = argparse.ArgumentParser(prog="shellindent sweep --scheduler")
    parser.add_argument("address")
    parser.add_argument("study")
    parser.add_argument("--out", required=True)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--timeout", type=float, default=10.0)
    a = parser.parse_args(argv)
    try:
        from distributed import Client
    except ImportError as e:
        return _error(a.address, f"dask.distributed cannot be imported by {sys.executable} "
                                 f"({e}); install it (Debian: apt-get install "
                                 f"python3-distributed; pip: dask[distributed])")
    try:
        client = Client(a.address, timeout=a.timeout)
    except Exception as e:  # OSError, TimeoutError, ValueError for a malformed address
        return _error(a.address, f"cannot reach the Dask scheduler within {a.timeout:g} s "
                                 f"({type(e).__name__}: {e})")
    try:
        result = sweep(a.study, client=client, out=a.out, quick=a.quick)
    except InputError as e:
        print(f"shellindent: error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("sweep: interrupted (Ctrl-C): the finished cases are kept; run the sweep again "
              "to finish it", file=sys.stderr)
        return 1
    finally:
        client.close()
    sys.stdout.write(result.csv)
    return 1 if result.failed else 0


if __name__ == "__main__":
    sys.exit(main())
