"""Field (trial-weight) balancing, the service behind ``rbcli field-balance``
(:data:`rbcli.api.commands.FIELD_BALANCE`): ``service`` (:func:`field_balance`, ``parse``,
``run``), ``job`` (read once), ``readings`` (``"6 mm/s rms@30"``, ``"10 g@0"``),
``coefficients`` (a trim run), ``shop`` (limits, holes, drawers), ``trial`` (a trial mass to
start with), ``compute`` (the result of a job), ``result`` (its values and JSON).
"""
