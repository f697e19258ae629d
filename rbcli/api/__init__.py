"""The services layer: rbcli's public Python API, one module per question.

Each module holds, for its command(s): a frozen options object parsed and checked once
(``XOptions.parse(body, **kwargs)``: values accepted as SI numbers or quantity strings by
:mod:`rbcli.api.options`, the body's defaults and their provenance resolved here), a
``run(body, options) -> XResult`` and the public function ``x(body, **kwargs)`` that does
both. Results are frozen dataclasses (:class:`rbcli.api.result.Result`) with ``to_json()``
and ``return_code``. Nothing here prints, draws or imports the command line.

=================  ==========================================
module             public functions (re-exported by ``rbcli``)
=================  ==========================================
``load``           ``load``, ``load_text``
``inertia``        ``inertia``
``principal``      ``principal``
``balance``        ``balance``
``field``          ``field_balance`` (a package: ``field.service`` and its parts)
``precess``        ``precess``
``top``            ``top``
``gyrocompass``    ``gyrocompass``
``rollcheck``      ``rollcheck``
``whirl``          ``whirl``
``report``         ``report``
=================  ==========================================

Shared: ``options`` (how a typed value is read), ``check`` (the arguments' types and sizes,
checked at the door of every public function), ``result`` (the ``Result`` mixin, the one
finiteness check), ``massprops`` (what inertia and principal share), ``shaft`` (the shaft's
line and its defaults).
"""

__all__: list[str] = []  # the modules are the API; rbcli re-exports the public functions
