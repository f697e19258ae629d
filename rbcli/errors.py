"""The one small error hierarchy of rbcli, and the exit status each error means.

Every layer raises these; only :mod:`rbcli.cli` prints them (as
``rbcli: file:line:col: message``) and turns them into exit codes. A check the user
asked for that fails (exit 1) is not an error: the command prints its full result and
exits 1 itself.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass


class ExitStatus(enum.IntEnum):
    """Exit codes of SPEC §4."""

    OK = 0
    CHECK_FAILED = 1  # a check the user asked for failed; the full result was printed
    BAD_INPUT = 2  # bad usage or bad input
    INTERNAL = 70  # a bug in rbcli
    INTERRUPTED = 130  # Ctrl-C


@dataclass(frozen=True)
class Location:
    """Where something is in an input file: 1-based line and column (0 = unknown)."""

    file: str
    line: int = 0
    col: int = 0

    def __str__(self) -> str:
        if self.line <= 0:
            return self.file
        if self.col <= 0:
            return f"{self.file}:{self.line}"
        return f"{self.file}:{self.line}:{self.col}"


class RbcliError(Exception):
    """Base of every error rbcli reports to the user."""

    exit_status: ExitStatus = ExitStatus.INTERNAL

    def __init__(self, message: str, where: Location | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.where = where

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message


class InputError(RbcliError):
    """Bad input: a body file, an option value, a mesh file. Exit 2."""

    exit_status = ExitStatus.BAD_INPUT


class NonFiniteResult(InputError):
    """A result came out as inf or NaN: the inputs are too large or too small to compute
    with (not a bug). Exit 2, like any other bad input.
    """
