#!/usr/bin/env python3
"""Coverage-guided fuzzing of rbcli's input layer with atheris (libFuzzer for Python).

Not run by pytest (the file name does not start with ``test_``) nor in CI: run it by hand
for as long as you like; see tests/fuzz/README.md. Each input is split by its first byte
into one of the targets below; the property is the promise of README ("Output, exit status
and speed"): whatever the bytes, the reader ends in a result or in rbcli's own InputError
(exit 2) — any other exception, a hang (``-timeout``) or a memory blow-up
(``-rss_limit_mb``) is a finding, and libFuzzer saves the input as ``crash-*``/``timeout-*``.

Targets
-------
0. a body file (YAML), through :func:`rbcli.body.bodyfile.load_text` (includes resolve in a
   scratch folder holding one small body, ``inc.yaml``);
1. a quantity with units, :func:`rbcli.io.units.parse_quantity`, and a unit,
   :func:`rbcli.io.units.parse_unit` (nested powers must be refused at once);
2. an option value, :func:`rbcli.api.options.vector` / ``quantity`` for a few kinds;
3. the text sanitiser, :func:`rbcli.env.clean`: its output never holds a control character
   or a line separator and never exceeds its bound.
"""

from __future__ import annotations

import os
import re
import sys
import tempfile
from pathlib import Path

import atheris

with atheris.instrument_imports():
    from rbcli.api import options
    from rbcli.env import MAX_LINE, clean
    from rbcli.errors import InputError
    from rbcli.io import units
    from rbcli.body.model import load_text

SCRATCH = Path(tempfile.mkdtemp(prefix="rbcli-fuzz-"))
(SCRATCH / "inc.yaml").write_text("{shape: box, mass: 1, size: [1, 1, 1]}\n")
KINDS = ["length", "mass", "angular_speed", "inertia", "dimensionless"]
CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def body(data: bytes) -> None:
    try:
        load_text(data, "<fuzz>", SCRATCH)
    except InputError:
        pass


def quantity(text: str) -> None:
    for fn in (units.parse_quantity, units.parse_unit):
        try:
            fn(text)
        except units.UnitError:
            pass


def option(text: str, kind: str) -> None:
    for fn in (options.vector, options.quantity):
        try:
            fn(text, kind, "--x")
        except InputError as exc:  # shown through clean(): one line whatever the value
            assert str(exc).startswith("--x"), str(exc)
            assert "\n" not in clean(f"rbcli: {exc}")


def sanitiser(text: str) -> None:
    out = clean(text)
    assert not CONTROL.search(out), repr(out)
    assert len(out) <= MAX_LINE + 1


def TestOneInput(raw: bytes) -> None:  # noqa: N802 - atheris' name
    fdp = atheris.FuzzedDataProvider(raw)
    target = fdp.ConsumeIntInRange(0, 3)
    if target == 0:
        body(fdp.ConsumeBytes(fdp.remaining_bytes()))
        return
    if target == 2:
        kind = KINDS[fdp.ConsumeIntInRange(0, len(KINDS) - 1)]
        option(fdp.ConsumeUnicodeNoSurrogates(fdp.remaining_bytes()), kind)
        return
    text = fdp.ConsumeUnicodeNoSurrogates(fdp.remaining_bytes())
    (quantity if target == 1 else sanitiser)(text)


def main() -> None:
    os.environ.setdefault("RBCLI_MAX_PARTS", "20000")  # bounded work per input
    atheris.Setup(sys.argv, TestOneInput)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
