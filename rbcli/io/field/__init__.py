"""The files of field balancing: ``jobfile`` (a job, YAML) and ``coefficients`` (saved
influence coefficients, JSON); here the words both take, which the command line and the
Python API take too (:data:`rbcli.api.commands.FIELD_BALANCE`)."""

#: the words a job file, a coefficients file and the parameters accept, per key
CHOICES = {
    "method": ("least-squares", "min-max", "exact"),
    "phase": ("lag", "lead"),
    "angle_sense": ("with", "against"),
    "rotation": ("cw", "ccw"),
    "measure": ("pk", "pk-pk", "rms"),
    "standard": ("iso20816-3",),
    "foundation": ("rigid", "flexible"),
    "robust": ("huber",),
    "numbering": ("with", "against"),
}


def plane_names(p: int) -> tuple[str, ...]:
    """The names of ``p`` planes a job does not name: A, B, ..., Z, then 27, 28, ..."""
    return tuple("ABCDEFGHIJKLMNOPQRSTUVWXYZ"[j] if j < 26 else str(j + 1) for j in range(p))
