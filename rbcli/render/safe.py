"""User text made safe inside every output: CSV, JSON, reports, robot XML, figures.

Names, labels and file names are data that came from a file or a command line. In an
output they must stay data: they may not forge lines or cells, reorder what a reader sees,
break the format's syntax or become a spreadsheet formula. The rules, one for every format:

- **Escaped everywhere** (:func:`escape`, the escapes of :func:`rbcli.env.clean` without
  its cutting of long words): C0 controls (NUL, ESC, CR, LF, TAB...), DEL, C1 controls
  (NEL ``\\x85``...), the line and paragraph separators U+2028/U+2029, the bidirectional
  controls U+200E/U+200F, U+202A-U+202E (embeddings and overrides) and U+2066-U+2069
  (isolates), the byte-order mark U+FEFF, and what XML 1.0 forbids in a document (the
  noncharacters U+FFFE/U+FFFF and lone surrogates, which UTF-8 cannot even encode). Each
  becomes visible text: ``\\n``, ``\\r``, ``\\t``, ``\\e`` (ESC), ``\\xNN``, ``\\uNNNN``.
- **Spreadsheet formulas** (:func:`csv_text`): a CSV text cell that starts with ``=``, ``+``,
  ``-``, ``@``, TAB or CR is prefixed with an apostrophe ``'`` — the OWASP "CSV Injection"
  advice (https://owasp.org/www-community/attacks/CSV_Injection; OWASP ASVS 5.0 requirement
  1.2.10): Excel, LibreOffice and Google Sheets then show the cell as text
  (the apostrophe is their "this is text" mark), and a script sees the apostrophe and can
  strip it. Numbers are never text cells, so ``-0.5`` stays a number.
- **JSON** (:func:`json_escape`): JSON itself escapes C0 controls; the other characters above
  are written as ``\\uXXXX`` escapes too. That is lossless (a JSON parser gives back the very
  same string), and the raw characters never reach a terminal that shows the JSON or a
  JavaScript engine that reads it as a literal (U+2028 ends a line there).

Stdlib only; patterns compiled on first use.
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
    """Encoded JSON text with the unsafe characters JSON leaves raw written as ``\\uXXXX``.

    They can stand only inside strings (JSON's own syntax is ASCII), so this is safe on the
    whole document. Plain ASCII without DEL has none of them: returned as it is, without
    compiling the pattern (~2 ms, on every ``--json`` run)."""
    if encoded.isascii() and "\x7f" not in encoded:
        return encoded
    return re.sub(_JSON_UNSAFE, _json_u, encoded)
