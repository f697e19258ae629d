"""Field (trial-weight) balancing, the service behind ``rbcli field-balance`` (physics sheet
``balance.md`` §5; the two-plane example is Brüel & Kjær's note 17-227): :func:`parse` reads
the job once, :func:`run` computes the result (:mod:`.compute`), whose ``to_json()`` is
``--json``. No body is needed."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbcli.api.commands import FIELD_BALANCE
from rbcli.api.field import compute
from rbcli.api.field.job import Job, located, make
from rbcli.api.field.result import FieldBalanceResult
from rbcli.api.params import function, read
from rbcli.api.result import jsonable
from rbcli.core.balance.common import BalanceValueError
from rbcli.errors import NonFiniteResult, ParamError, literal

__all__ = ["FieldBalanceResult", "field_balance", "parse", "run"]

#: the core's parameter names that are not the parameters of :func:`field_balance` (any other
#: name the core gives is "run")
_CORE_PARAMS = {"v0": "initial", "trials": "trial", "limits": "limit", **{p.name: p.name for p in FIELD_BALANCE}}


def parse(body: None = None, **kwargs: Any) -> Job:
    """The keyword arguments of :func:`field_balance` (see there) read and checked: the job
    (:class:`rbcli.api.field.job.Job`).

    Raises
    ------
    rbcli.InputError
        with the message the command line prints (``trial: ...``), located in the job file
        for a job file's value.
    """
    return make(read(body, FIELD_BALANCE, kwargs))


def run(body: None, job: Job) -> FieldBalanceResult:
    """Field balancing of ``job`` (``body`` is None: the command needs none).

    Raises
    ------
    rbcli.InputError
        readings that give no influence coefficient or a singular matrix (``run: ...``);
        :class:`rbcli.NonFiniteResult` when the result overflows.
    """
    try:
        with np.errstate(all="ignore"):
            try:
                res = compute.result(job)
            except BalanceValueError as exc:
                raise ParamError(_CORE_PARAMS.get(exc.param, "run"), literal(exc)) from None
            except np.linalg.LinAlgError as exc:
                raise ParamError("run", literal(exc)) from None
            jsonable(res.to_json())  # the one finiteness check: refuses inf and NaN
    except (OverflowError, ZeroDivisionError, NonFiniteResult):
        why = "the result overflows (a number beyond 1e308): the readings or trial masses are too large or too small"
        raise (located(ParamError("run", why), (), job.source) if job.source is not None else
               NonFiniteResult("{initial}, {trial}, {run}: " + why)) from None
    except ParamError as exc:
        raise located(exc, job.options.given, job.source) from None
    return res


@function(FIELD_BALANCE, body="none")
def field_balance(body: None = None, **kwargs: Any) -> FieldBalanceResult:
    """Field (trial-weight) balancing from vibration readings: influence coefficients.

    Readings are ``"amplitude@phase"`` (degrees from the keyphasor), all bare (``"6.0@30"``,
    one relative scale) or all of one kind (``"40 um@30"``, ``"6 mm/s rms@30"``, ``"0.5
    g@30"``: g is gravity); trial masses ``"mass@angle"`` (``"10 g@0"``, bare: grams). A
    number given for a quantity is SI (m, kg, rad/s, N).

    Parameters
    ----------
    {parameters}

    Returns
    -------
    FieldBalanceResult
        ``corrections[i].mass`` kg, ``angle_deg`` in the sense of the trial angles.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter.
    rbcli.InputError
        naming the parameter (``param``), or located in a job file.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.field_balance(initial="6.0@30", trial="10 g@0", run="4.0@110")
    >>> round(r.corrections[0].mass * 1e3, 2)   # g
    9.08
    """
    return run(None, parse(None, **kwargs))
