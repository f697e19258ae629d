"""rbcli — a command-line calculator for the general motion of rigid bodies."""

__version__ = "0.1.0"
