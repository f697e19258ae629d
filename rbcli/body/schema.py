"""The JSON Schema (draft-07) of the body file, from the loader's own tables, for editors:
``rbcli schema`` prints it; ``rbcli/data/body.schema.json`` is it (a test keeps it so).
"""

from __future__ import annotations

import json
from pathlib import Path

from rbcli.body.bodyfile import UNIT_KEYS
from rbcli.body.givenpart import INERTIA_NAMES
from rbcli.body.partlist import SPECIAL_SHAPES, part_keys
from rbcli.core.shapes import SHAPES
from rbcli.io.bearingtable import schema as bearing_schema

SCHEMA_PATH = Path(__file__).resolve().parent.parent / "data" / "body.schema.json"

QUANTITY = {
    "description": "a number in the file's units, or a string with a unit such as '30 cm'",
    "anyOf": [{"type": "number"}, {"type": "string", "pattern": "^\\s*[-+]?[0-9.]"}],
}


def _vec(n: int) -> dict:
    return {"type": "array", "items": {"$ref": "#/definitions/quantity"}, "minItems": n, "maxItems": n}


def _param_schema(key: str, shape: str) -> dict:
    kind = SHAPES[shape].kind(key)
    if kind.name == "length":
        return {"$ref": "#/definitions/quantity"}
    if kind.name == "lengths":
        return _vec(kind.n)  # plate size [a, b]; box size, semi_axes [a, b, c]
    if kind.name == "points":
        return {"type": "array", "items": _vec(3), "minItems": kind.n, "maxItems": kind.n}
    return {"type": "boolean"}


COMMON = {
    "name": {"type": "string"},
    "subtract": {"type": "boolean", "description": "true for a hole or pocket: the mass is removed"},
    "cut_from": {"type": "string", "description": "a hole takes the density of this part"},
    "at": {**_vec(3), "description": "where the part's local origin sits in the body frame"},
    "axis": {**_vec(3), "description": "turn the part's local z onto this direction"},
    "rotate": {"$ref": "#/definitions/rotate"},
    "mass": {"$ref": "#/definitions/quantity"},
    "density": {"$ref": "#/definitions/quantity"},
    "areal_density": {"$ref": "#/definitions/quantity"},
    "linear_density": {"$ref": "#/definitions/quantity"},
    "material": {"type": "string", "description": "a material by name (rbcli materials, or the "
                 "body's materials:): its density"},
}


_INERTIA_MAP = {
    "type": "object",
    "properties": {**{k: {"$ref": "#/definitions/quantity"} for names in INERTIA_NAMES.values()
                      for k in names}, "convention": {"enum": ["tensor", "positive"]}},
    # each diagonal entry under one of its names; no entry under two
    "allOf": [*({"anyOf": [{"required": [n]} for n in INERTIA_NAMES[d]]} for d in ("Ixx", "Iyy", "Izz")),
              *({"not": {"required": [a, b]}} for names in INERTIA_NAMES.values()
                for i, a in enumerate(names) for b in names[i + 1:])],
    "additionalProperties": False,
}
#: the keys of the special parts (mesh, step, given, include) beside :data:`COMMON`
SPECIAL_KEYS = {
    "file": {"type": "string", "description": "relative to this file: a mesh (STL, binary or "
             "ASCII, or OBJ), a STEP file (.step, .stp) or a body file (include)"},
    "scale": {"type": "number", "exclusiveMinimum": 0},
    "units": {"type": "string", "description": "the length unit of the file's coordinates"},
    "allow_open": {"type": "boolean"},
    "weld": {"description": "merge vertices closer than this length to close gaps (default: "
             "from the file's precision), or exact",
             "anyOf": [{"$ref": "#/definitions/quantity"}, {"const": "exact"}]},
    "part": {"type": "string", "description": "only the solids this name or pattern matches"},
    "solids": {"type": "object", "description": "a material or density per solid name or pattern",
               "additionalProperties": {"anyOf": [{"type": "string"}, {"type": "number"}]}},
    "com": _vec(3),
    "inertia": {"anyOf": [{"type": "array", "items": _vec(3), "minItems": 3, "maxItems": 3},
                          _INERTIA_MAP]},
    "convention": {"enum": ["tensor", "positive"], "description": "how a 3x3 inertia's "
                   "off-diagonal entries read: the tensor's (−∫xy dm) or products of inertia "
                   "(+∫xy dm); required when they are non-zero"},
}


def _part_variant(shape: str, props: dict, required: list[str]) -> dict:
    return {
        "if": {"properties": {"shape": {"const": shape}}, "required": ["shape"]},
        "then": {"properties": props, "required": required, "additionalProperties": False},
    }


def _variants(extra: dict) -> list[dict]:
    """One if/then per shape; ``extra`` adds keys every shape accepts (the single-part form
    also takes the body's ``units`` and ``rbcli``)."""
    variants = []
    for name, info in SHAPES.items():
        props = {"shape": {"const": name}, **COMMON, **extra}
        for key in (*info.required, *info.optional):
            props[key] = _param_schema(key, name)
        for dkey, rkey in info.diameters.items():
            props[dkey] = {**_param_schema(rkey, name), "description": f"2 × {rkey} (give one of them)"}
        if name == "rod":
            props["from"] = _vec(3)
            props["to"] = _vec(3)
        required = ["shape"] + ([] if name == "rod" else [k for k in info.required if k not in info.diameters.values()])
        variant = _part_variant(name, props, required)
        for dkey, rkey in info.diameters.items():
            either = [{"required": [dkey]}, {"required": [rkey]}]
            if rkey in info.required:
                variant["then"].setdefault("allOf", []).append({"oneOf": either})
            else:
                variant["then"].setdefault("allOf", []).append({"not": {"required": [dkey, rkey]}})
        variants.append(variant)
    for shape in SPECIAL_SHAPES:  # their keys: the loader's, each as SPECIAL_KEYS says
        props = {k: {**COMMON, **SPECIAL_KEYS}[k] for k in part_keys(shape) if k != "shape"}
        both = {**props, **extra, "shape": {"const": shape}}
        if "units" in props and "units" in extra:  # a one-part mesh/STEP body: a text is the file's
            both["units"] = {"anyOf": [props["units"], extra["units"]]}
        variants.append(_part_variant(shape, both,
                                      ["shape", *(("mass", "inertia") if shape == "given" else ("file",))]))
    return variants


def body_schema() -> dict:
    shapes = [*SHAPES, *SPECIAL_SHAPES]
    part = {
        "type": "object",
        "properties": {"shape": {"enum": shapes}},
        "required": ["shape"],
        "allOf": _variants({}),
    }
    units = {
        "type": "object",
        "properties": {k: {"type": "string"} for k in UNIT_KEYS},
        "additionalProperties": False,
        "description": "what bare numbers mean (default SI; bare angles are degrees, bare angular "
        "speeds rad/s unless angular_speed names a unit such as rpm)",
    }
    point = {"anyOf": [_vec(3), {"enum": ["com", "origin"]}]}
    body = {
        "type": "object",
        "properties": {
            "rbcli": {"const": 1},
            "name": {"type": "string"},
            "description": {"type": "string"},
            "units": {"$ref": "#/definitions/units"},
            "materials": {"type": "object", "description": "your own materials: name: density",
                          "additionalProperties": {"$ref": "#/definitions/quantity"}},
            "parts": {"type": "array", "items": {"$ref": "#/definitions/part"}, "minItems": 1},
            "reference": point,
            "shaft": {
                "type": "object",
                "properties": {"axis": _vec(3), "through": _vec(3)},
                "required": ["axis"],
                "additionalProperties": False,
            },
            "pivot": _vec(3),
            "rim_radius": {"$ref": "#/definitions/quantity"},
            "bearings": bearing_schema(),
        },
        "required": ["parts"],
        "additionalProperties": False,
    }
    # the one-part shorthand: a part that may also carry the body's units and version
    shorthand = {
        "type": "object",
        "properties": {"shape": {"enum": shapes}},
        "required": ["shape"],
        "allOf": _variants({"units": {"$ref": "#/definitions/units"}, "rbcli": {"const": 1}}),
    }
    rotate = {
        "type": "object",
        "oneOf": [
            {"properties": {"axis": _vec(3), "angle": {"$ref": "#/definitions/quantity"}}, "required": ["axis", "angle"], "additionalProperties": False},
            {"properties": {"euler": {"type": "array", "items": {"$ref": "#/definitions/quantity"}, "minItems": 1, "maxItems": 3}, "seq": {"type": "string", "pattern": "^([xyz]{1,3}|[XYZ]{1,3})$"}}, "required": ["euler", "seq"], "additionalProperties": False},
            {"properties": {"quaternion": _vec(4)}, "required": ["quaternion"], "additionalProperties": False},
            {"properties": {"matrix": {"type": "array", "items": _vec(3), "minItems": 3, "maxItems": 3}}, "required": ["matrix"], "additionalProperties": False},
        ],
    }
    return {
        "$schema": "http://json-schema.org/draft-07/schema#",
        "$id": "https://rbcli.invalid/body.schema.json",
        "title": "rbcli body file",
        "description": "A rigid body for rbcli: parts with shapes, placement and mass (see `rbcli shapes`).",
        "definitions": {"quantity": QUANTITY, "units": units, "part": part, "rotate": rotate, "body": body},
        "anyOf": [{"$ref": "#/definitions/body"}, shorthand],
    }


def schema_text() -> str:
    return json.dumps(body_schema(), indent=2, ensure_ascii=False) + "\n"
