"""Field (trial-weight) balancing: the service behind ``rbcli field-balance``.

================  ========================================================================
``service``       :func:`~rbcli.api.field.service.field_balance`, ``parse`` and ``run``
``job``           the job read once, from the parameters or a job file
``readings``      reading texts (``"6 mm/s rms@30"``) and trial masses (``"10 g@0"``)
``coefficients``  a trim run: stored influence coefficients brought into a job
``shop``          what the shop allows and has: mass and reading limits, holes, drawers
``trial``         a trial mass to start with: what sizes it, and the suggestion
``compute``       the result of a job: the solve, the masses as fitted, the zones
``result``        :class:`~rbcli.api.field.result.FieldBalanceResult` and its parts
================  ========================================================================

Its parameters are :data:`rbcli.api.commands.FIELD_BALANCE`.
"""
