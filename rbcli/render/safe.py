"""User text made safe inside every output: CSV, JSON, reports, robot XML, figures (the
rule as users read it: rbcli(1), :mod:`rbcli.cli.catalog`). Names, labels and file names
stay data: no forged lines or cells, broken syntax or spreadsheet formula.

- :func:`escape`: every character of :data:`UNSAFE` (controls, separators, bidirectional
  controls, what XML 1.0 forbids) as visible text (``\\n``, ``\\e``, ``\\xNN``, ``\\uNNNN``).
- :func:`csv_text`: a text cell starting with ``=``, ``+``, ``-``, ``@``, TAB or CR gets an
  apostrophe in front (OWASP "CSV Injection"; ASVS 5.0 1.2.10).
- :func:`json_escape`: those JSON leaves raw written as ``\\uXXXX`` escapes (lossless).
"""

from __future__ import annotations

import re

#: every character escaped in every output (see the module docstring)
UNSAFE = ("[\x00-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069\ufeff"
          "\ud800-\udfff\ufffe\uffff]")
#: those a JSON encoder leaves as they are (it escapes C0 itself)
_JSON_UNSAFE = "[\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069\ufeff\ud800-\udfff\ufffe\uffff]"
_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t", "\x1b": "\\e"}

#: the first characters that make a spreadsheet read a cell as a formula (OWASP)
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def _visible(m: re.Match) -> str:
    c = m.group()
    named = _NAMED.get(c)
    if named is not None:
        return named
    n = ord(c)
    return f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}"


def escape(text: object, keep: str = "") -> str:
    """``text`` with every unsafe character (module docstring) written as a visible escape;
    the characters in ``keep`` (e.g. ``"\\n\\t"`` for a file shown whole) stay as they are."""
    s = text if isinstance(text, str) else str(text)
    pattern = "(?![" + re.escape(keep) + "])" + UNSAFE if keep else UNSAFE
    return re.sub(pattern, _visible, s)


def csv_text(text: object) -> str:
    """A CSV text cell: :func:`escape`, then an apostrophe before a formula's first character."""
    s = escape(text)
    return "'" + s if s.startswith(FORMULA_START) else s


def _json_u(m: re.Match) -> str:
    return f"\\u{ord(m.group()):04x}"


def json_escape(encoded: str) -> str:
    """Encoded JSON text with the unsafe characters JSON leaves raw (only in strings) written
    as ``\\uXXXX``; plain ASCII without DEL is returned as it is (no pattern compiled: ~2 ms)."""
    if encoded.isascii() and "\x7f" not in encoded:
        return encoded
    return re.sub(_JSON_UNSAFE, _json_u, encoded)
