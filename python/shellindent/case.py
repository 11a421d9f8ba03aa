"""Cases: read from a YAML file, parsed from YAML text, or built from a dict with unit strings.

Every way goes through the C++ case-file reader of `shellindent run` (io/case_file), so a case is
validated exactly as the CLI validates it and a bad one raises InputError with the CLI's text.
A dict is first written as YAML text (case_yaml) and parsed as such; its messages name `label`
and the line of that text.
"""

import json
import os
import re
from collections.abc import Mapping

from . import _core

Case = _core.Case

# A string the YAML writer may leave unquoted: words, numbers with units, dotted names.
_PLAIN = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.+\-/ ]*")
_YAML_WORDS = {"true", "false", "yes", "no", "on", "off", "null", "~", "y", "n"}


def _scalar(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if v is None:
        return "null"
    if isinstance(v, (int, float)):
        return repr(v)
    s = str(v)
    if _PLAIN.fullmatch(s) and s == s.strip() and s.lower() not in _YAML_WORDS:
        return s
    return json.dumps(s, ensure_ascii=False)  # a JSON string is a YAML double-quoted scalar


def _lines(value, indent):
    pad = "  " * indent
    out = []
    if isinstance(value, Mapping):
        for k, v in value.items():
            if isinstance(v, (Mapping, list, tuple)) and len(v) > 0:
                out.append(f"{pad}{_scalar(k)}:")
                out += _lines(v, indent + 1)
            else:
                out.append(f"{pad}{_scalar(k)}: {_flow(v)}")
    else:
        for v in value:
            if isinstance(v, (Mapping, list, tuple)) and len(v) > 0:
                nested = _lines(v, indent + 1)
                out.append(f"{pad}- {nested[0].lstrip()}")
                out += nested[1:]
            else:
                out.append(f"{pad}- {_flow(v)}")
    return out


def _flow(v):
    if isinstance(v, Mapping):
        return "{}"
    if isinstance(v, (list, tuple)):
        return "[]"
    return _scalar(v)


def case_yaml(case_dict):
    """The YAML text of a case given as a dict (nested dicts, lists and scalars).

    Quantities are strings with their unit, as in a case file: {"laminate": {"layup":
    "[0/90]2S", "ply_thickness": "0.475 mm"}, "path": {"depth_max": "2 mm"}}.
    """
    if not isinstance(case_dict, Mapping):
        raise TypeError("a case dict must be a mapping, not " + type(case_dict).__name__)
    return "\n".join(_lines(case_dict, 0)) + "\n"


def parse_case(text, label="<text>"):
    """A case from YAML text; `label` stands for the file name in error messages."""
    return _core.parse_case(text, label)


def default_case():
    """The built-in default of `shellindent run`: the source paper's cap, [0/0]2S, 0-10 mm."""
    return _core.default_case()


def _looks_like_yaml(s):
    return "\n" in s or ": " in s


def read_case(source, label=None):
    """A case from a Case, a dict, a YAML file path or YAML text.

    A str is YAML text when it holds a newline or ": ", otherwise a file name. `label` names
    the case in error messages (default: the file name, "<dict>" or "<text>").
    """
    if isinstance(source, Case):
        return source
    if isinstance(source, Mapping):
        return _core.parse_case(case_yaml(source), label or "<dict>")
    if isinstance(source, os.PathLike):
        return _core.read_case(os.fspath(source))
    if isinstance(source, str):
        if _looks_like_yaml(source):
            return _core.parse_case(source, label or "<text>")
        return _core.read_case(source)
    raise TypeError("a case is a shellindent.Case, a dict, a path or YAML text, not "
                    + type(source).__name__)
