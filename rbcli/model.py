"""The body model: what a body file means, in SI, after validation.

A leaf module (stdlib + numpy only) shared by io (which builds it) and core and
render (which read it). Every vector is in the body frame.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rbcli.errors import Location


@dataclass(frozen=True)
class Part:
    """One part of a body, placed in the body frame.

    Attributes
    ----------
    name : str — the part's name (``sub/part`` for parts of an included file)
    shape : str — the shape name of SPEC §1
    mass : float — kg, always positive; ``subtract`` says whether it is removed
    subtract : bool — True for a hole or pocket (its mass is taken away)
    com : (3,) ndarray — m, the part's centre of mass
    inertia_com : (3, 3) ndarray — kg m^2, about the part's com, body axes, tensor convention
    measure : float | None — the part's volume (m^3), area (m^2) or length (m)
    measure_kind : str — "volume", "area", "length", "point" or "given"
    radius : float | None — m, the outer radius of a round part (disk, ring, cylinder, ...)
    axis : (3,) ndarray — the part's local z axis in the body frame
    extra : dict — shape-specific facts worth reporting (e.g. a mesh's volume and area)
    where : Location | None — where the part is defined
    """

    name: str
    shape: str
    mass: float
    subtract: bool
    com: np.ndarray
    inertia_com: np.ndarray
    measure: float | None = None
    measure_kind: str = "point"
    radius: float | None = None
    axis: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]))
    extra: dict = field(default_factory=dict)
    where: Location | None = None

    @property
    def signed_mass(self) -> float:
        """kg, negative for a subtracted part."""
        return -self.mass if self.subtract else self.mass


@dataclass(frozen=True)
class Shaft:
    """A shaft line: unit ``axis`` through the point ``through`` (m)."""

    axis: np.ndarray
    through: np.ndarray


@dataclass(frozen=True)
class Body:
    """A validated body: its parts and the defaults commands use.

    Attributes
    ----------
    name : str
    source : str — the file path, ``<stdin>`` or ``<expr>``
    text : str — the input text as read (for reports: echo and SHA-256)
    parts : tuple[Part, ...]
    reference, pivot : (3,) ndarray | None — m
    reference_is_com : bool — ``reference: com`` in the file
    shaft : Shaft | None
    rim_radius : float | None — m
    description : str
    warnings : tuple[str, ...] — located warnings to show on standard error
    inputs : tuple[str, ...] — real paths of every file read to build the body: the body
        file, every include at any depth and every mesh file (outputs must avoid them);
        empty for standard input or ``-e`` unless those include files or meshes
    units : dict[str, str] — the file's ``units`` (``{"length": "mm", ...}``): what its bare
        numbers mean; empty for SI
    """

    name: str
    source: str
    text: str
    parts: tuple[Part, ...]
    reference: np.ndarray | None = None
    reference_is_com: bool = False
    shaft: Shaft | None = None
    pivot: np.ndarray | None = None
    rim_radius: float | None = None
    description: str = ""
    warnings: tuple[str, ...] = ()
    inputs: tuple[str, ...] = ()
    units: dict = field(default_factory=dict)
