"""Each command's parameters, declared once.

A command's parameters are a tuple of :class:`Param` (its table in
:mod:`rbcli.api.commands`): name, how a value is read (``kind``, ``quantity``), help, and
the command line's form and default. Made from it: the public function's signature, door
checks and *Parameters* (:func:`function`); the values read into SI once (:func:`read` ->
:class:`Options`); the typer options, ``--help`` and man page
(:func:`rbcli.cli.common.command`); the options echo (:func:`rbcli.render.echo.echo_rows`)
and the CSV unit of each echoed value (:func:`si_unit`). In a help text ``{param}`` names a
parameter: ``stiffness_y`` in a docstring, ``--stiffness-y`` in ``--help``."""

from __future__ import annotations

import functools
import inspect
import textwrap
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from rbcli.api import check
from rbcli.api import options as op
from rbcli.errors import ParamError, option_name, param_name, spell

__all__ = ["Param", "Options", "read", "checkers", "function", "document", "si_unit"]

#: how a value of each reading kind is checked at the door of the API (:mod:`rbcli.api.check`)
#: and what its docstring says it takes; a quantity ("quantity", "values", "vector") reads
#: numbers of ``Param.quantity`` by the unit rule
KINDS: dict[str, str] = {
    "quantity": "float or str",
    "values": "str, float or sequence",
    "vector": "str or (3,) sequence",
    "point": "'com', 'origin', str or (3,) sequence",
    "direction": "'x', 'y', 'z', str or (3,) sequence",
    "degrees": "float or str",
    "grade": "float or str",
    "tolerance": "float or str",
    "count": "int",
    "ints": "int, str or sequence of int",
    "choice": "str",
    "text": "str",
    "texts": "str or sequence of str",
    "nested": "str, or a sequence of str or of sequences of str",
    "numbers": "str or sequence of float",
    "fraction": "float or str",
    "flag": "bool",
    "path": "str or os.PathLike",
}


@dataclass(frozen=True)
class Param:
    """One parameter of a command.

    Attributes
    ----------
    name : str — the Python keyword; the option is ``--`` + it with dashes, or the command's
        own word (:data:`rbcli.errors.COMMAND_OPTIONS`)
    help : str — what it means and what a bare number is in; ``{param}`` names another
    kind : str — how a value is read (:data:`KINDS`)
    quantity : str — the quantity kind of its numbers (:data:`rbcli.io.units.KINDS`)
    counts : tuple of int — how many comma-separated values ``values`` takes
    choices : tuple of str — the words ``choice`` takes
    form : str — ``"option"``, ``"options"`` (given once per item) or ``"argument"``
    valid : callable, optional — ``valid(value, given)``: None when allowed, else why not (a
        message template, raised as a ParamError naming this parameter)
    echo : str — how the options table shows it (default from ``kind``); ``"-"`` never
    echo_default : bool — shown when not given too, marked "(default)"
    default, metavar, cli_type — the command line's default, metavar and type
    cli, api : bool — whether the command line / the Python API takes it"""

    name: str
    help: str
    kind: str = "text"
    quantity: str = ""
    counts: tuple[int, ...] = (1,)
    choices: tuple[str, ...] = ()
    form: str = "option"
    valid: Callable[[Any, Any], str | None] | None = field(default=None, repr=False, compare=False)
    echo: str = ""
    echo_default: bool = False
    default: Any = None
    metavar: str | None = None
    cli_type: type | None = None
    cli: bool = True
    api: bool = True
    most: int = field(default=0, repr=False)

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"{self.name}: unknown kind {self.kind!r}")
        object.__setattr__(self, "most", max(self.counts))

    @property
    def checker(self) -> Callable[[Any, str], Any]:
        """The type check at the door of the API (:mod:`rbcli.api.check`)."""
        k = self.kind
        if k in ("quantity", "degrees", "grade", "tolerance", "fraction"):
            return check.quantity
        if k == "values":
            return check.values(self.most) if self.most > 1 else check.quantity
        if k in ("vector", "point", "direction"):
            return check.vector
        if k == "count":
            return check.count
        if k == "ints":
            return check.integers(self.most)
        if k == "texts":
            return check.texts(1, self.most)
        if k == "nested":
            return check.texts(2)
        if k == "numbers":
            return check.values(check.MAX_ITEMS)
        if k == "flag":
            return _flag
        if k == "path":
            return check.path
        return check.text

    @property
    def shows(self) -> str:
        """How the options table shows the value (:attr:`echo`, or derived from the kind)."""
        if self.echo:
            return self.echo
        if self.kind in ("quantity", "values", "vector"):
            return self.quantity
        return {"degrees": "deg", "point": "point", "direction": "direction", "grade": "grade",
                "count": "count", "tolerance": "percent", "fraction": "percent"}.get(self.kind, "text")


#: the tolerance of a nearly symmetric body, shared by top, gyrocompass, rollcheck and whirl
SYMMETRY_TOL = Param(
    "symmetry_tol",
    "How far from symmetric about its axis the body may be: the two moments across the "
    "axis may differ, and the products of inertia coupling the axis to the plane across "
    "it may be, up to this fraction of their mean (0.01 or '1 %'; at most 10 %). Within "
    "it the answer is for the symmetrised body (the mean moment across) with a warning; "
    "beyond it the body is refused. Default: 1 %.", "tolerance")


def _flag(value: Any, param: str) -> bool | None:
    return None if value is None else check.flag(value, param)


@dataclass(frozen=True)
class Options:
    """The parameters of one call, read once: each value in SI (None: not given).

    ``o.speed`` is the value of parameter ``speed``; :attr:`given` names those the caller gave
    (one equal to the command line's default is not given), :attr:`typed` the unit typed
    after a number (``("mass_step", "g")``), :attr:`raw` each value as given (for labels),
    :attr:`params` the command's table.
    """

    params: tuple[Param, ...]
    values: tuple[tuple[str, Any], ...]
    given: tuple[str, ...] = ()
    typed: tuple[tuple[str, str], ...] = ()
    raw: tuple[tuple[str, Any], ...] = ()

    def __getattr__(self, name: str) -> Any:
        for key, value in self.__dict__.get("values", ()):
            if key == name:
                return value
        raise AttributeError(f"no parameter {name!r}")

    def source(self, name: str) -> str:
        """Where the value of ``name`` came from: ``name`` when it was given, else
        ``"default"`` (the JSON's ``..._source`` keys)."""
        return name if name in self.given else "default"

    def replace(self, **values: Any) -> Options:
        """These options with some values replaced (a service's reading that needs the
        others: per-bearing lists, the body's defaults)."""
        unknown = set(values) - {k for k, _ in self.values}
        if unknown:
            raise AttributeError(f"no parameter {sorted(unknown)[0]!r}")
        return Options(self.params, tuple((k, values.get(k, v)) for k, v in self.values),
                       self.given, self.typed, self.raw)

    def unit_typed(self, name: str) -> bool:
        """The value of ``name`` was typed with its unit (``"3000 rpm"``, not ``3000``)."""
        return name in dict(self.typed)

    def as_given(self, name: str) -> Any:
        """The value of ``name`` as the caller gave it (None: not given)."""
        return dict(self.raw).get(name)


def checkers(params: tuple[Param, ...]) -> dict[str, Callable[[Any, str], Any]]:
    """The API's type check of each parameter (for :func:`rbcli.api.check.arguments`)."""
    return {p.name: p.checker for p in params if p.api}


def as_text(v: Any) -> str:
    """A value as the caller gave it, for a message (numbers by ``repr``)."""
    if isinstance(v, str):
        return v
    if isinstance(v, (list, tuple)):
        return ",".join(as_text(x) for x in v)
    return repr(v)


def _read_one(u: op.Units, p: Param, value: Any) -> Any:
    k, name = p.kind, p.name
    if k == "quantity":
        return u.quantity(value, p.quantity, name)
    if k == "values":
        return tuple(u.numbers(value, p.quantity, name, counts=p.counts))
    if k == "vector":
        return tuple(u.vector(value, p.quantity, name))
    if k == "point":
        v = u.point(value, name)
        return v if isinstance(v, str) else tuple(v)
    if k == "direction":
        return tuple(op.direction(value, name))
    if k == "degrees":
        return op.degrees(value, name)
    if k == "grade":
        return op.grade(value, name)
    if k == "tolerance":
        return op.symmetry_tolerance(value, name)
    if k == "fraction":
        return op.fraction(value, name)
    if k == "choice":
        return op.choice(value.strip().lower() if isinstance(value, str) else value, name,
                         p.choices)
    return value  # count, ints, text, texts, nested, numbers, flag, path: as checked (the service reads them)


def read(body: Any, params: tuple[Param, ...], given: Mapping[str, Any]) -> Options:
    """The values ``given`` (keyword arguments, or the command line's options) read in SI
    for ``body`` (its bare units, :class:`rbcli.api.options.Units`), in table order.

    Raises
    ------
    rbcli.InputError
        one line naming the parameter (``bearings: ...``).
    """
    u = op.Units.of(body)
    values, named = [], []
    for p in params:
        raw = value = given.get(p.name)
        if value is not None or p.kind == "tolerance":  # (None: the default tolerance)
            with op.naming(p.name):
                value = _read_one(u, p, value)
            why = p.valid(value, raw) if p.valid is not None and raw is not None else None
            if why is not None:
                raise ParamError(p.name, why)
        if raw is not None and not (p.default is not None and value == p.default):
            named.append(p.name)
        values.append((p.name, value))
    return Options(params, tuple(values), tuple(named), tuple(u.typed.items()),
                   tuple((k, v) for k, v in given.items() if v is not None))


def document(params: tuple[Param, ...]) -> str:
    """The numpydoc entries of ``params`` (4-space indented, as in a function's docstring);
    an entry of the command line only is named as its option (``--csv``)."""
    cli_only = {p.name for p in params if not p.api}
    out = []
    for p in params:
        if p.api:
            text = spell(p.help, lambda n: option_name(n) if n in cli_only else param_name(n))
            if p.default not in (None, False) and "Default" not in text:
                text += f" Default: {p.default}."
            text = textwrap.fill(text, 92, initial_indent=" " * 8, subsequent_indent=" " * 8)
            out.append(f"    {p.name} : {KINDS[p.kind]}, optional\n{text}")
    return "\n".join(out)


def function(params: tuple[Param, ...], *, body: str = "required") -> Callable[[Callable], Callable]:
    """Make ``fn(body, **kwargs)`` a public function of ``params``: its signature and the
    parameters of its docstring (which has ``{parameters}`` where they go) from the table,
    and its arguments checked at the door (``body`` an :class:`rbcli.Body`, or None when
    ``body="optional"``, none at all when ``body="none"``: ``fn`` gets None; each keyword
    by :attr:`Param.checker`), arithmetic errors deep inside as one
    :class:`rbcli.NonFiniteResult` (:func:`rbcli.api.check.arithmetic`)."""
    kinds = checkers(params)
    optional = body == "optional"
    takes_body = body != "none"

    def wrap(fn: Callable) -> Callable:
        @functools.wraps(fn)
        def public(body: Any = None, **kwargs: Any) -> Any:
            if takes_body:
                body = check.body(body, optional=optional)
            elif body is not None:
                raise TypeError(f"{fn.__name__}() takes no body, keyword arguments only")
            kw = check.arguments(kinds, **kwargs)
            with check.arithmetic(kw):
                return fn(body, **kw)

        first = [inspect.Parameter("body", inspect.Parameter.POSITIONAL_OR_KEYWORD,
                                   default=None if optional else inspect.Parameter.empty)]
        public.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
            first * takes_body + [inspect.Parameter(p.name, inspect.Parameter.KEYWORD_ONLY, default=None)
                                  for p in params if p.api],
            return_annotation=inspect.signature(fn).return_annotation)
        public.__doc__ = (fn.__doc__ or "").replace("    {parameters}", document(params))
        return public

    return wrap


#: the SI unit of each quantity kind, as the CSV writes it (pint reads it)
SI_UNITS = {"length": "m", "mass": "kg", "time": "s", "angular_speed": "rad/s", "speed": "m/s",
            "acceleration": "m/s^2", "stiffness": "N/m", "damping": "N*s/m", "angle": "deg",
            "unbalance": "kg*m", "dimensionless": "1", "force": "N"}


def si_unit(p: Param) -> str:
    """The SI unit of a parameter's value as the JSON echoes it (the CSV's unit column)."""
    if p.kind in ("quantity", "values", "vector"):
        return SI_UNITS.get(p.quantity, "")
    if p.kind in ("point",):
        return "m"
    if p.kind in ("degrees",):
        return "deg"
    if p.kind == "grade":
        return "mm/s"
    if p.kind in ("direction", "tolerance", "fraction", "count", "ints", "numbers"):
        return "1"
    return ""


