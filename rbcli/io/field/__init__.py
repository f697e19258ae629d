"""The files of field balancing: ``jobfile`` (a job, YAML) and ``coefficients`` (saved
influence coefficients, JSON)."""
