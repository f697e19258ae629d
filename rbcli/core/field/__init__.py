"""Field (trial-weight) balancing by influence coefficients (physics sheet ``balance.md`` §5).

================  ========================================================================
``solve``         the influence matrix; exact, least-squares and min-max corrections, limits
``cone``          least squares and min-max under limits (second-order cones)
``fit``           corrections as fitted (rounded, or split onto positions)
``drawer``        the best weights from a drawer at the holes: an exact search
``trial``         the trial mass to start with
``significance``  Darlow's plane-significance factors
``severity``      reading measures and kinds, ISO 20816-3 zones
================  ========================================================================
"""
