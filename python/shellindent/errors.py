"""The exceptions of shellindent: the C++ toolkit's errors, raised with the CLI's message.

str(error) is exactly what `shellindent` prints after "shellindent: error: ", e.g.
"case.yaml:4: laminate.ply_thickness = '-1 mm': must be positive". The parts of the message are
attributes too: file, line (1-based; None where unknown), key (the dotted key), value (as
written) and reason (the message without its location).
"""


class Error(Exception):
    """An error of the toolkit; InputError, NumericalError or InternalError."""

    def __init__(self, message, *, file=None, line=None, key=None, value=None, reason=None):
        super().__init__(message)
        self.file = file
        self.line = line
        self.key = key
        self.value = value
        self.reason = reason if reason is not None else message


class InputError(Error, ValueError):
    """Bad input: a case (file, text or dict) or an argument the toolkit cannot use (CLI exit 2)."""


class NumericalError(Error, RuntimeError):
    """A numerical failure outside a path run (a path run reports its own status instead)."""


class InternalError(Error, RuntimeError):
    """A broken invariant of the toolkit: a bug to report."""
