"""``rbcli shapes``, ``rbcli materials``, ``rbcli schema`` and ``rbcli examples``."""

from __future__ import annotations

from pathlib import Path

import typer

from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

SPECIAL = {
    "mesh": (
        "a uniform solid bounded by a closed triangle mesh from a file: STL (binary or ASCII) "
        "or OBJ (polygons fanned into triangles); the table and JSON add its volume, area and "
        "triangle count",
        "file (relative to the body file); optional scale (a plain factor), units (of the "
        "mesh's coordinates, e.g. mm; default: the body file's length unit), weld (a length, or "
        "exact: how far apart the copies of a vertex may be; default from the file's "
        "precision), allow_open (true: accept boundary edges, with a warning)",
        "mass or density (a hole in a mesh, or a mesh hole, may use cut_from)",
        "the mesh's own coordinate origin (file coordinates x scale x units), not its centroid",
        "exact volume, centroid and second moments of the polyhedron (divergence theorem, about "
        "the bounding-box centre: a part far from the origin keeps its digits). Refused, naming "
        "the file: unreadable, truncated or malformed; NaN or infinite coordinates; not closed "
        "(how many boundary edges) unless allow_open; non-manifold edges; mixed orientation; "
        "no volume. A mesh facing inward is turned outward, with a warning. Vertices with equal "
        "coordinates are merged; if the mesh is then open, boundary vertices closer than the "
        "weld tolerance too (CAD noise such as 0 next to -3.79e-33), with a warning giving the "
        "largest gap (default: 4 float32 ulps of the largest coordinate for binary STL, 1e-9 of "
        "the bounding-box diagonal for ASCII STL and OBJ; at most 1e-3 of the mesh's size); "
        "welding decides closedness only. At most 1 GiB (RBCLI_MAX_MESH_BYTES)",
    ),
    "step": (
        "each solid of a STEP file a part (pip install 'rbcli[cad]'), named from the file, "
        "placed by its assembly; the JSON adds its unit and colour",
        "file (.step, .stp); optional part (a name or pattern: 'link*'), solids ({pattern: "
        "material or density}), units, scale (override the file's unit)",
        "mass (shared by volume), density or material",
        "the file's origin",
        "exact from each solid's B-rep (OpenCascade); hostile or open files refused at their "
        "line (README, Budgets)",
    ),
    "given": (
        "measured or CAD-exported mass properties",
        "mass, com (local frame), inertia about the com: a 3x3 matrix with convention: tensor "
        "(off-diagonals -∫xy dm) or positive (products +∫xy dm) beside it, required when an "
        "off-diagonal is non-zero; or {Ixx, Iyy, Izz, Ixy, Iyz, Izx, convention: tensor | "
        "positive}",
        "mass",
        "the part frame (com is given in it)",
        "as given; checked to be symmetric and physically possible",
    ),
    "include": (
        "another body file as a sub-assembly",
        "file (relative to this file)",
        "the included file's own",
        "the included body's frame",
        "the included body's parts, placed with at/axis/rotate",
    ),
}


def examples_dir() -> Path:
    """Where the bundled examples are: inside the installed package, or the source tree's."""
    here = Path(__file__).resolve().parent.parent
    for cand in (here / "examples", here.parent / "examples"):
        if cand.is_dir():
            return cand
    return here / "examples"


@app.command(help="The shape catalogue: parameters, local origin, mass keys and formulas.")
def shapes(
    name: str = typer.Argument(None, help="Show one shape only.", show_default=False),
    json_: bool = c.JsonOpt,
) -> None:
    from rbcli.core.shapes import SHAPES
    from rbcli.errors import InputError
    from rbcli.io.yamlvalues import suggest

    rows = []
    for info in SHAPES.values():
        params = ", ".join([*info.required, *(f"[{o}]" for o in info.optional)]) or "—"
        if info.name == "rod":
            params += " (or from, to)"
        if info.diameters:  # diameter: wherever radius: is accepted (inner_diameter likewise)
            params += " (" + ", ".join(f"{d} for {r}" for d, r in info.diameters.items()) + ")"
        rows.append((info.name, info.summary, params, info.density_keys, info.origin, info.formulas))
    for key, (summary, params, mass, origin, formulas) in SPECIAL.items():
        rows.append((key, summary, params, mass, origin, formulas))
    if name is not None:
        rows = [r for r in rows if r[0] == name]
        if not rows:
            names = [*SHAPES, *SPECIAL]
            raise InputError(f"unknown shape '{name}'{suggest(name, names)} (shapes: "
                             f"{', '.join(names)})")
    e = c.env()
    if json_:
        from rbcli.render.jsonout import dumps

        keys = ("shape", "summary", "parameters", "mass", "origin", "formulas")
        e.write(dumps([dict(zip(keys, r)) for r in rows]))
        return
    text = []
    for shape, summary, params, mass, origin, formulas in rows:
        text.append(
            f"{shape}\n  {summary}\n  parameters: {params}\n  mass: {mass}\n"
            f"  local origin: {origin}\n  inertia: {formulas}\n"
        )
    text.append(
        "Every part also takes name, at [x, y, z], axis [x, y, z] or rotate {...}, and\n"
        "subtract: true (a hole; with cut_from: NAME it takes that part's density).\n"
        "Symmetry axis = local z. Inertia formulas are about the part's centre of mass.\n"
    )
    e.write("\n".join(text))


@app.command(help="The built-in materials: density and where it is from.")
def materials(
    name: str = typer.Argument(None, help="Only names holding this.", show_default=False),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
) -> None:
    from rbcli.body.materials import key, table
    from rbcli.errors import InputError, literal

    rows = [m for m in table() if any(key(name or "") in key(n) for n in (m.name, *m.aliases))]
    if not rows:
        raise InputError(f"no built-in material matches '{literal(name)}'")
    c.emit(c.env(), c.output_format(json_, fmt), lambda: [m._asdict() for m in rows],
           lambda doc: doc.table("materials", ("material", "density [kg/m³]", "also", "source"),
                                 [(m.name, f"{m.density:g}", ", ".join(m.aliases), m.source)
                                  for m in rows], right=(1,)))


@app.command(help="The JSON Schema (draft-07) of the body file, for editors.")
def schema(
    path: bool = typer.Option(False, "--path", help="Print where the installed schema file is, for a yaml-language-server modeline."),
) -> None:
    from rbcli.body.schema import SCHEMA_PATH, schema_text

    e = c.env()
    if path:
        e.write(f"{SCHEMA_PATH}\n")
    else:
        e.write(schema_text())


@app.command(help="List the bundled example bodies, or print one.")
def examples(
    name: str = typer.Argument(None, help="Example to print (with or without .yaml).", show_default=False),
    path: bool = typer.Option(False, "--path", help="Print the example's path instead of its text."),
) -> None:
    from rbcli.errors import InputError

    d = examples_dir()
    files = sorted(p for p in d.glob("*.yaml"))
    e = c.env()
    if name is None:
        lines = []
        for p in files:
            first = _title(p)
            lines.append(f"{p.stem:<24} {first}")
        e.write("\n".join(lines) + ("\n" if lines else ""))
        if path:
            e.write(f"{d}\n")
        return
    stem = name[:-5] if name.endswith(".yaml") else name
    match = [p for p in files if p.stem == stem]
    if not match:
        from rbcli.io.yamlvalues import suggest

        raise InputError(f"no bundled example '{name}'{suggest(stem, [p.stem for p in files])} "
                         "(see `rbcli examples`)")
    e.write(f"{match[0]}\n" if path else match[0].read_text(encoding="utf-8"))


def _title(p: Path) -> str:
    for line in p.read_text(encoding="utf-8").splitlines():
        if line.startswith("name:"):
            return line[5:].strip().strip("'\"")
    return ""


MANUAL["shapes"] = {
    "notes": [f"A {k} part (shape: {k}), {summary}: parameters {params}; mass: {mass}; local "
              f"origin: {origin}; inertia: {formulas}." for k, (summary, params, mass, origin,
                                                             formulas) in SPECIAL.items()
              if k in ("mesh", "step")],
    "examples": [
        ("rbcli shapes cylinder", "The cylinder's parameters, local origin and formulas."),
        ("rbcli shapes mesh", "The mesh part's keys and what rbcli checks in a mesh file."),
        ("rbcli shapes step", "The STEP part's keys and what rbcli checks in a STEP file."),
    ],
}
MANUAL["materials"] = {
    "notes": ["The table: rbcli/data/materials.csv; names match ignoring case and hyphens."],
    "json": [("name, aliases, density, source", "one object per material; density in kg/m^3.")],
    "examples": [("rbcli materials steel", "The steels, their densities and sources.")],
}
MANUAL["schema"] = {
    "notes": [
        "Put '# yaml-language-server: $schema=PATH' as the first line of a body file, with "
        "PATH from 'rbcli schema --path', and editors with the YAML language server check the "
        "file as you type.",
    ],
    "examples": [("rbcli schema --path", "Where the installed schema file is.")],
}
MANUAL["examples"] = {
    "examples": [
        ("rbcli examples", "List the bundled examples."),
        ("rbcli inertia \"$(rbcli examples cube --path)\"", "Run a bundled example."),
    ],
}
MANUAL[""] = {
    "notes": [
        "A body file is YAML: a list of parts (point, rod, ring, disk, plate, triangle, box, "
        "cylinder, sphere, hemisphere, cone, ellipsoid, torus, mesh, step, given, include), each "
        "placed with at, axis or rotate, with a mass, a density or a material (rbcli-materials(1)), "
        "and subtract: true for holes. Bare "
        "numbers are in the file's units (SI unless 'units:' says otherwise; bare angles are "
        "degrees, bare angular speeds rad/s unless units: names an angular_speed such as rpm); "
        "any number may be a string with a unit, such as '30 cm', '2.5 lb', '7850 kg/m^3', "
        "'12 deg' or '1200 rpm'; the spellings people type are read too (lbs, pound, pounds, "
        "inch, inches, in., ft, foot, feet, mph, ft/s), and a unit is echoed in one spelling "
        "(RPM as rpm). See rbcli-shapes(1).",
        "A bare density follows the file's units too: density: 7850 in a body whose length unit "
        "is mm is 7850 kg/mm^3. A density (or areal or linear density) that no matter has — "
        "above osmium's 22 590 kg/m^3, or for a solid part below the lightest aerogels — is "
        "warned once per body, with the value in kg/m^3 and the reading probably meant (did "
        "you mean \"7850 kg/m^3\"?).",
        "Bare numbers on the command line mean what they would mean in that body's file: "
        "lengths and masses in the body's units (SI for -e and for files without units), angles "
        "in degrees, angular speeds in rad/s unless the body's units has angular_speed (e.g. "
        "rpm), everything else SI; with several bodies each uses its own units; commands without "
        "a body (field-balance, gyrocompass --ratio) state their defaults in --help. Tables start "
        "with the options as understood, each in the unit typed (--mass-step '0.5 g' shows "
        "0.5 g) or, for a bare number, the unit it was read in (angular speeds also in rpm or "
        "rad/s; JSON stays SI); an error quotes the value with its unit (got -180 mm); a value more than 10 body sizes away or a rim faster than sound (at a speed typed "
        "without its unit) gets a one-line warning naming the option.",
        "Errors are one line on standard error, 'rbcli: file:line:column: message', with no "
        "traceback.",
        "Output formats: every command that prints tables takes --format table (the default), "
        "json (the same as --json) or csv. The CSV is the JSON as one table, the same layout "
        "for every command and stable across versions: the header quantity,value,text,unit, "
        "then one row per value of the JSON. quantity is the value's JSON path, unique in the "
        "table: keys joined by dots, list positions in brackets counted from 0 (mass, com[2], "
        "inertia[1][2], corrections[0].mass). value holds numbers only: full precision (Python's "
        "repr, which reads back to the same double) unless --digits N is given, then N "
        "significant figures; it is empty for text and for a number the JSON marks as not "
        "defined (a <name>_deg whose <name>_defined is false, shown as a dash in the tables). "
        "text holds strings and the booleans true and false. unit is the number's SI unit as "
        "in the JSON (kg, m, kg*m^2, rad/s, deg, N*s/m; 1 for a dimensionless number; "
        "field-balance readings: their SI unit, or reading for bare numbers), as each "
        "command's JSON section states it. A null, an empty list or an empty object is a row "
        "with value and text empty. With several bodies a file column comes first and the "
        "header is written once. --units changes the tables only: the CSV is SI, like the "
        "JSON. RFC 4180 quoting, one line per row: csv.reader(open(f, newline='')) and "
        "pandas.read_csv(f) read it in one call.",
        "User text in every output is data: control characters (C0, DEL, C1), the line and "
        "paragraph separators and the bidirectional controls (U+200E/F, U+202A-202E, "
        "U+2066-2069) are shown escaped (\\n, \\e, \\x85, \\u202e) in tables, CSV, reports, "
        "robot XML and figures, and written as \\uXXXX escapes in JSON (lossless). A CSV text "
        "cell that starts with =, +, -, @, tab or carriage return gets an apostrophe in front "
        "(the OWASP advice against spreadsheet formula injection: spreadsheets show it as "
        "text); numbers are never text cells, so -0.5 stays a number.",
        "Shell completion: rbcli --show-completion SHELL prints the script for bash, zsh, fish "
        "or powershell (eval \"$(rbcli --show-completion bash)\"); rbcli --install-completion "
        "SHELL installs it.",
    ],
    "examples": [
        ("rbcli inertia examples/square_lamina.yaml", "Mass properties of a bundled example."),
        ("rbcli principal -e '{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}'", "An inline body."),
    ],
}
