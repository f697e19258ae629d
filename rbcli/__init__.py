"""rbcli — rigid-body mechanics: a command-line calculator and a Python library.

The Python API runs the same computations as the commands::

    import rbcli
    body = rbcli.load("examples/two_disk_rotor.yaml")
    r = rbcli.balance(body, planes="0,400 mm", radius="100 mm", speed="3000 rpm")
    r.corrections[0].mass        # kg
    r.to_json()                  # what `rbcli balance ... --json` prints (less "file")

Bodies are read (:func:`load`, :func:`load_text`, :func:`load_data`) or built in code
(:mod:`rbcli.parts` and :meth:`Body.from_parts`). Functions: :func:`inertia`, :func:`principal`,
:func:`balance`, :func:`field_balance`, :func:`precess`, :func:`top`,
:func:`gyrocompass`, :func:`rollcheck`, :func:`whirl`, :func:`report`. Keyword arguments take SI numbers
or quantity strings (``"30 cm"``, ``"3000 rpm"``) read exactly as the command line reads
them. A bad value raises :class:`InputError`, a ``ValueError`` (``.message``, ``.where``,
``.param``) naming the parameter (``spin: ...``; the command line prints ``--spin: ...``); a
wrong type a ``TypeError`` naming it. Every function checks its arguments first
(:mod:`rbcli.api.check`). ``import rbcli`` is cheap: each function loads its
modules on first use.
"""

from __future__ import annotations

# not `from typing import ...`: typing costs ~2-5 ms, and the `rbcli` console script imports
# this package before rbcli.interrupts can handle Ctrl-C (rbcli.__main__)
TYPE_CHECKING = False

__version__ = "0.1.0"

#: public name -> the module that defines it (loaded on first use, PEP 562)
_API = {
    "load": "rbcli.api.load",
    "load_text": "rbcli.api.load",
    "load_data": "rbcli.api.load",
    "inertia": "rbcli.api.inertia",
    "principal": "rbcli.api.principal",
    "balance": "rbcli.api.balance",
    "field_balance": "rbcli.api.field.service",
    "precess": "rbcli.api.precess",
    "top": "rbcli.api.top",
    "gyrocompass": "rbcli.api.gyrocompass",
    "rollcheck": "rbcli.api.rollcheck",
    "whirl": "rbcli.api.whirl",
    "report": "rbcli.api.report",
    "report_text": "rbcli.documents",
    "write_report": "rbcli.documents",
    "Body": "rbcli.model",
    "InputError": "rbcli.errors",
    "ParamError": "rbcli.errors",
    "NonFiniteResult": "rbcli.errors",
    "ExitStatus": "rbcli.errors",
}

#: public submodules (loaded on first use too)
_MODULES = {"parts": "rbcli.parts"}

__all__ = ["__version__", *_API, *_MODULES]

if TYPE_CHECKING:  # pragma: no cover
    from typing import Any

    from rbcli import parts  # noqa: F401
    from rbcli.api.load import load, load_data, load_text  # noqa: F401
    from rbcli.errors import ExitStatus, InputError, NonFiniteResult, ParamError  # noqa: F401
    from rbcli.model import Body  # noqa: F401


def __getattr__(name: str) -> Any:
    module = _API.get(name)
    if module is None:
        if name in _MODULES:
            import importlib

            return importlib.import_module(_MODULES[name])  # sets rbcli.parts itself
        raise AttributeError(f"module 'rbcli' has no attribute '{name}'")
    import importlib

    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # the next lookup is a plain attribute
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
