"""Field (trial-weight) balancing by influence coefficients (physics sheet ``balance.md`` §5).

================  ========================================================================
``classic``       the one- and two-plane solves, as rbcli always did them
``solve``         the influence matrix; exact, least-squares and min-max corrections
``fit``           corrections as fitted (rounded, or split onto positions)
``trial``         the trial mass to start with
``significance``  Darlow's plane-significance factors
``severity``      reading measures and kinds, ISO 20816-3 zones
================  ========================================================================
"""
