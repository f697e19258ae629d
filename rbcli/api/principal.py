"""Principal moments and axes about a point: :func:`principal` (``rbcli principal``).

::

    import rbcli
    p = rbcli.principal(rbcli.load("examples/square_lamina.yaml"))
    p.moments, p.axes        # ascending, rows = unit axes in the body frame
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rbcli.api.commands import PRINCIPAL
from rbcli.api.inertia import Reference, part_rows, plausibility, snap, with_parts
from rbcli.api.params import Options, function, read
from rbcli.api.result import Result
from rbcli.core.inertia import body_mass_props
from rbcli.core.principal import principal_report

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["PrincipalResult", "parse", "run", "principal"]


@dataclass(frozen=True)
class PrincipalResult(Result):
    """Principal moments and axes about a point (``rbcli principal``).

    Attributes
    ----------
    name : str; mass : float — kg
    reference : (3,) ndarray — m, the point; reference_label : str — how tables name it
    moments : (3,) ndarray — kg m², ascending
    axes : (3, 3) ndarray — row i the unit axis of ``moments[i]`` (a proper rotation)
    symmetry : str — ``"asymmetric"``, ``"symmetric"`` or ``"spherical"``
    unique_axis : int or None — for ``"symmetric"``, the index of the moment that differs
    free_axes : tuple of int — the axes free to choose (equal moments)
    stable, stability : tuple of 3 — free rotation about each axis: stable (bool), and
        ``"stable"``, ``"unstable"`` or ``"neutral"`` (an axis of a symmetric body's equal pair)
    direction_angles_deg : (3, 3) ndarray — degrees, principal axis i from body axis j
    tilt_deg, tilt_axis — degrees, each axis from its nearest body axis line (``"x"``...)
    rotation_axis, rotation_angle_deg — the rotation taking the body axes to axes 1, 2, 3
    equivalent_box, equivalent_ellipsoid : (3,) ndarray — m, the uniform box's sides and
        ellipsoid's semi-axes with the same mass and moments
    parts : tuple of dict — each part's contribution (:func:`part_rows`)
    warnings : tuple of str — a point far outside the body's scale"""

    name: str
    mass: float
    reference: Any
    reference_label: str
    moments: Any
    axes: Any
    symmetry: str
    unique_axis: int | None
    free_axes: tuple[int, ...]
    stable: tuple[bool, bool, bool]
    direction_angles_deg: Any
    rotation_axis: Any
    rotation_angle_deg: float
    equivalent_box: Any
    equivalent_ellipsoid: Any
    stability: tuple[str, str, str] = ("stable", "stable", "stable")
    tilt_deg: Any = None
    tilt_axis: tuple[str, str, str] = ("x", "y", "z")
    parts: tuple[dict, ...] = ()
    warnings: tuple[str, ...] = field(default=())

    def to_json(self) -> dict[str, Any]:
        """What ``rbcli principal BODY --json`` prints, less ``"file"`` (SI)."""
        return with_parts({
            "reference": self.reference,
            "moments": self.moments,
            "axes": snap(self.axes, scale=1.0, rtol=1e-15),
            "symmetry": self.symmetry,
            "stable": list(self.stable),
            "mass": self.mass,
            "free_axes": [i + 1 for i in self.free_axes],
            "direction_angles_deg": self.direction_angles_deg,
            "rotation_axis": self.rotation_axis,
            "rotation_angle_deg": self.rotation_angle_deg,
            "equivalent_box": self.equivalent_box,
            "equivalent_ellipsoid": self.equivalent_ellipsoid,
            "stability": list(self.stability),
            "tilt_deg": self.tilt_deg,
            "tilt_axis": list(self.tilt_axis),
            "name": self.name,
        }, self.parts)


def parse(body: Body | None, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`principal` read for ``body`` (None: SI, before a body
    is read): :class:`rbcli.api.params.Options`."""
    return read(body, PRINCIPAL, kwargs)


def run(body: Body, options: Options) -> PrincipalResult:
    """:func:`principal` with options already read (:func:`parse`)."""
    ref = Reference.of(body, options, default="com")
    mp = body_mass_props(body)
    point, J = ref.inertia(mp)
    pr = principal_report(mp.mass, J, point)
    pa = pr.axes_info
    return PrincipalResult(
        name=body.name, mass=pr.mass, reference=pr.reference, reference_label=ref.label,
        moments=pa.moments, axes=pa.axes, symmetry=pa.symmetry, unique_axis=pa.unique_axis,
        free_axes=tuple(pa.free_axes), stable=pr.stable,
        direction_angles_deg=pr.direction_angles_deg, rotation_axis=pr.rotation_axis,
        rotation_angle_deg=pr.rotation_angle_deg, equivalent_box=pr.equivalent_box,
        equivalent_ellipsoid=pr.equivalent_ellipsoid, stability=pr.stability,
        tilt_deg=pr.tilt_deg, tilt_axis=tuple("xyz"[j] for j in pr.tilt_axis),
        parts=part_rows(body), warnings=plausibility(body, ref))


@function(PRINCIPAL)
def principal(body: Body, **kwargs: Any) -> PrincipalResult:
    """Principal moments and axes about a point (``about``, default the com), symmetry,
    stability of free rotation and the equivalent uniform box and ellipsoid.

    Parameters
    ----------
    body : rbcli.Body
    {parameters}

    Returns
    -------
    PrincipalResult
        ``to_json()`` is what ``rbcli principal BODY --json`` prints, less ``"file"``.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter; a point so
        far away that the inertia overflows.

    Notes
    -----
    Free rotation about the axes of the largest and smallest moment is stable, about the
    intermediate one unstable (Landau & Lifshitz, *Mechanics*, §37).

    Examples
    --------
    >>> import rbcli
    >>> p = rbcli.principal(rbcli.load("examples/square_lamina.yaml"), about="origin")
    >>> [round(float(m), 6) for m in p.moments]                # m a²/12, 7 m a²/12, 2 m a²/3
    [0.083333, 0.583333, 0.666667]
    >>> p.symmetry
    'asymmetric'"""
    return run(body, parse(body, **kwargs))
