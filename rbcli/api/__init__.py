"""The services layer: rbcli's public Python API, one module per question.

Each command's parameters are declared once in :mod:`rbcli.api.commands` (machinery:
:mod:`rbcli.api.params`); its module has ``parse(body, **kwargs)`` (the values read once,
in SI), ``run(body, options) -> XResult`` and the public function made by ``@function``.
Results are frozen dataclasses (:class:`rbcli.api.result.Result`) with ``to_json()`` and
``return_code``. Nothing here prints, draws or imports the command line.

Modules: ``load``, ``inertia``, ``principal``, ``balance``, ``field`` (a package),
``precess``, ``top``, ``gyrocompass``, ``rollcheck``, ``whirl``, ``report`` (each public
function re-exported by ``rbcli``); shared: ``options`` (reading a typed value), ``check``
(the door), ``result``, ``shaft`` (the shaft's line and defaults)."""

__all__: list[str] = []  # the modules are the API; rbcli re-exports the public functions
