"""The process environment a command runs in: streams, terminal, colour.

Injectable so that tests can play a pipe or a terminal (the httpie way).
"""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass
from typing import IO


@dataclass
class Env:
    stdout: IO[str]
    stderr: IO[str]
    stdout_isatty: bool
    color: bool
    width: int | None = None
    debug: bool = False
    #: set once standard output has been closed by its reader (``| head -1``): there is no
    #: one left to read, so a batch may stop early
    pipe_closed: bool = False

    @classmethod
    def from_process(cls) -> "Env":
        try:
            tty = sys.stdout.isatty()
        except (AttributeError, ValueError):
            tty = False
        no_color = "NO_COLOR" in os.environ or os.environ.get("TERM") == "dumb"
        return cls(sys.stdout, sys.stderr, tty, color=tty and not no_color)

    def write(self, text: str) -> None:
        """Write to standard output; a closed pipe (``| head -1``) is quiet."""
        try:
            self.stdout.write(text)
            self.stdout.flush()
        except BrokenPipeError:
            self.pipe_closed = True
            silence_stdout()

    def warn(self, text: str) -> None:
        try:
            self.stderr.write(text.rstrip("\n") + "\n")
            self.stderr.flush()
        except BrokenPipeError:
            pass


def silence_stdout() -> None:
    """After a closed pipe, point stdout at /dev/null so the final flush is quiet."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):
        pass
