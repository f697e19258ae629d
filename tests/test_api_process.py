"""A library leaves the process alone (issue 22 item 5), and threads get the answers one
thread gets.

Every public function is called in this process: afterwards the garbage collector is as it
was (enabled, nothing frozen), ``os.environ``, the warning filters, numpy's error state and
the locale are unchanged. Eight threads calling rbcli at once get exactly the results of one.
"""

from __future__ import annotations

import gc
import locale
import os
import threading
import warnings

import numpy as np

import rbcli
from conftest import EXAMPLES

CALLS = [
    lambda: rbcli.inertia(rbcli.load(EXAMPLES / "bracket.yaml"), omega=[1, 2, 3]),
    lambda: rbcli.principal(rbcli.load(EXAMPLES / "housing.yaml")),
    lambda: rbcli.balance(rbcli.load(EXAMPLES / "two_disk_rotor.yaml"), planes="0,400 mm",
                          radius="100 mm", speed="3000 rpm", bearings="0,400 mm", grade="G6.3"),
    lambda: rbcli.precess(rbcli.load(EXAMPLES / "book.yaml"), omega=[0.01, 1, 0.01]),
    lambda: rbcli.top(rbcli.load(EXAMPLES / "top.yaml"), spin=150, theta=30),
    lambda: rbcli.gyrocompass(rbcli.load(EXAMPLES / "gyroscope.yaml"), spin="6000 rpm", latitude=30),
    lambda: rbcli.rollcheck(rbcli.load(EXAMPLES / "penny.yaml"), speed="3 m/s"),
    lambda: rbcli.whirl(rbcli.load(EXAMPLES / "fan_rotor.yaml"), bearings="0,500 mm",
                        stiffness="5 N/um", damping="1 N*s/mm", speed="1480 rpm"),
    lambda: rbcli.field_balance(initial="6.0@30", trial="10 g@0", run="4.0@110"),
    lambda: rbcli.report(rbcli.load(EXAMPLES / "top.yaml"), spin=150, theta=30),
    lambda: rbcli.load_text("shape: box\nmass: 2\nsize: [0.1, 0.2, 0.3]\n"),
]


def _state():
    return (gc.isenabled(), gc.get_freeze_count(), gc.get_threshold(), dict(os.environ),
            list(warnings.filters), np.geterr(), locale.setlocale(locale.LC_ALL))


def test_calls_leave_the_process_alone():
    gc.unfreeze()  # a test run before may have frozen objects; what counts is that rbcli does not
    before = _state()
    for call in CALLS:
        call()
    assert _state() == before


def _json(r):
    return r.to_json() if hasattr(r, "to_json") else repr(r)


def test_eight_threads_get_the_answers_of_one():
    expected = [_json(call()) for call in CALLS]
    results: dict[int, list] = {}
    errors: list[BaseException] = []
    start = threading.Barrier(8)

    def work(i: int) -> None:
        try:
            start.wait()
            order = CALLS[i % len(CALLS):] + CALLS[:i % len(CALLS)]  # each thread its own order
            got = [_json(call()) for call in order]
            k = i % len(CALLS)
            results[i] = got[len(CALLS) - k:] + got[:len(CALLS) - k]
        except BaseException as exc:  # noqa: BLE001 - reported below
            errors.append(exc)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=600)
    assert not errors, errors
    assert len(results) == 8
    for got in results.values():
        assert got == expected  # exactly: the same floats, not approximately
