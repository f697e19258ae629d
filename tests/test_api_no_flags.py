"""No message of the Python API speaks the command line's ``--flags`` (issue 22 item 2).

Every golden case (``tests/cases``) is replayed through the Python API — the command's
function, its options as keyword arguments (the command line's option names mapped to the
parameters: ``rollcheck --axle`` is ``shaft``, ``--radius`` ``rim_radius``) — and every error
and every warning that comes out must contain no ``--`` outside the user's quoted text.
The command line's own output stays byte for byte what the golden files say
(``tests/test_golden.py``): there the same messages spell options, at the edge.
The hostile arguments of ``tests/test_api_hostile.py`` are checked the same way there.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

import rbcli
from rbcli.errors import COMMAND_OPTIONS, option_name
from conftest import ROOT, sampled_params

CASES = sorted((ROOT / "tests" / "cases").glob("*/*.yaml"))

#: command -> the API function
FUNCTIONS = {"inertia": "inertia", "principal": "principal", "balance": "balance",
             "field-balance": "field_balance", "whirl": "whirl", "precess": "precess",
             "top": "top", "gyrocompass": "gyrocompass", "rollcheck": "rollcheck"}

#: options that choose what is printed or written, not what is computed
OUTPUT_ONLY = {"--json", "--format", "--units", "--digits", "--csv", "--products", "--principal",
               "--plot", "--apply", "--force", "--report", "--save-coefficients"}

#: options that are flags (no value)
FLAGS = {"--verify", "--suggest-trial", "--cumulative", "--full", "--json", "--principal",
         "--force"}

def _renamed() -> dict[str, dict[str, str]]:
    """Options whose parameter is another word in one command (errors.COMMAND_OPTIONS, reversed)."""
    return {name: {opt: param for param, opt in table.items()} for name, table in COMMAND_OPTIONS.items()}


def _call(args: list[str]):
    """The API call a command line means: (function, body or None, keyword arguments), or
    None for a command the API has no function for."""
    cmd = args[0]
    if cmd not in FUNCTIONS:
        return None
    names = _renamed().get(cmd, {})
    body = None
    kw: dict = {}
    it = iter(args[1:])
    for a in it:
        if a.startswith("-") and a != "-":
            opt, eq, value = a.partition("=")
            if opt in FLAGS and not eq:
                if opt not in OUTPUT_ONLY:
                    kw[names.get(opt, opt[2:].replace("-", "_"))] = True
                continue
            if not eq:
                value = next(it)
            if opt in OUTPUT_ONLY:
                continue
            if opt in ("-e", "--expr"):
                body = ("text", value)
                continue
            param = names.get(opt, opt[2:].replace("-", "_"))
            if param in ("samples", "points", "positions") and re.fullmatch(r"[0-9]+", value):
                value = int(value)
            if param in kw:  # given twice (field-balance --trial): a list
                kw[param] = [*kw[param], value] if isinstance(kw[param], list) else [kw[param], value]
            else:
                kw[param] = value
        elif cmd == "field-balance":  # its argument is a job file, not a body
            kw["job"] = a
        else:
            body = ("file", a)
    return FUNCTIONS[cmd], body, kw


def _outside_quotes(text: str) -> str:
    return re.sub(r"'[^']*'", "''", text)


@pytest.mark.parametrize("case", sampled_params(CASES, lambda p: hash(p.name) % 4 == 0 or "err" in p.name,
                                                ids=lambda p: f"{p.parent.name}/{p.stem}"))
def test_api_messages_name_parameters_not_flags(case: Path, monkeypatch):
    monkeypatch.chdir(ROOT)
    spec = yaml.safe_load(case.read_text(encoding="utf-8"))
    call = _call(spec["args"])
    if call is None:
        pytest.skip("no API function for this command")
    name, body, kw = call
    texts = []
    try:
        b = None
        if body is not None:
            b = rbcli.load_text(body[1]) if body[0] == "text" else rbcli.load(body[1])
        fn = getattr(rbcli, name)
        r = fn(b, **kw) if name != "field_balance" else fn(**kw)
        texts += [str(w) for w in r.warnings]
        texts += [str(n) for n in getattr(r, "notes", ()) or ()]
    except (rbcli.InputError, TypeError) as exc:
        texts.append(str(exc))
    for t in texts:
        assert "--" not in _outside_quotes(t), f"{spec['args']}: {t}"


def test_the_replay_can_fail():
    # the mapping reaches the API: a golden error case gives the API's error, without --
    name, body, kw = _call(["rollcheck", "examples/penny.yaml", "--axle", "x", "--radius", "-1"])
    assert name == "rollcheck" and kw == {"shaft": "x", "rim_radius": "-1"}
    with pytest.raises(rbcli.InputError) as info:
        rbcli.rollcheck(rbcli.load(ROOT / body[1]), **kw)
    assert str(info.value).startswith("rim_radius: ") and "--" not in str(info.value)
    assert info.value.spelled(option_name) != str(info.value)
