"""YAML text of plain data (:func:`dump`) that rbcli's YAML 1.2 reader
(:mod:`rbcli.io.yamlsafe`) reads back identically: how a body is written
(:mod:`rbcli.body.document`)."""

from __future__ import annotations

import re

import yaml

__all__ = ["dump"]

#: plain scalars that the YAML 1.2 core schema reads as something other than a string
_NOT_STR = re.compile(
    r"~|null|Null|NULL|true|True|TRUE|false|False|FALSE"
    r"|[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+"
    r"|[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?"
    r"|[-+]?(\.inf|\.Inf|\.INF)|\.nan|\.NaN|\.NAN"
    r"|<<"  # a merge key, which body files refuse plain
)


def dump(data: object) -> str:
    """YAML text of plain data that rbcli's YAML 1.2 loader reads back identically.

    PyYAML quotes by the YAML 1.1 rules and would leave ``1e3`` (a number in YAML 1.2)
    bare: every string that starts like a number, null or boolean is double-quoted here.
    """
    return yaml.dump(data, Dumper=_Dumper, sort_keys=False, allow_unicode=True,
                     default_flow_style=None, width=100)


class _Dumper(getattr(yaml, "CSafeDumper", yaml.SafeDumper)):  # type: ignore[misc]
    def ignore_aliases(self, data: object) -> bool:
        return True  # a value used twice is written twice (body files refuse aliases)


def _str(dumper: yaml.SafeDumper, value: str) -> yaml.Node:
    style = '"' if (not value or _NOT_STR.fullmatch(value)) else None
    return dumper.represent_scalar("tag:yaml.org,2002:str", value, style=style)


_Dumper.add_representer(str, _str)
