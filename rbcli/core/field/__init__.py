"""Field balancing by influence coefficients (physics sheet ``balance.md`` §5): ``solve``
(exact, least-squares, min-max, limits), ``cone`` (second-order cones), ``fit`` (rounded or
split), ``drawer`` (a drawer's best weights), ``trial``, ``significance`` (Darlow),
``severity`` (measures, ISO 20816-3).
"""
