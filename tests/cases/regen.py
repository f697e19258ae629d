"""Write (or rewrite) the golden cases: ``python tests/cases/regen.py [--new-only]``.

A case is ``tests/cases/<command>/<name>.yaml`` holding ``args`` (the command line after
``rbcli``, paths relative to the repository root) and ``exit``; beside it ``<name>.out``
and ``<name>.err`` hold standard output and standard error, byte for byte. The test
``tests/test_golden.py`` runs every case in-process and compares. Rewriting them is a
deliberate act: say in the commit which outputs changed and why.

``CASES`` below lists the command lines; run this script after adding one.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE.parent))

from tests_blas import pin_blas_kernel  # noqa: E402  (before numpy: the kernel decides last digits)

pin_blas_kernel()

EXAMPLES = sorted(p.stem for p in (ROOT / "examples").glob("*.yaml"))

#: bodies of revolution about z (a wheel, a top, a disk): rollcheck and top apply
ROUND = ["bicycle_wheel", "car_wheel", "frisbee", "gyroscope", "hoop", "penny", "spoked_wheel",
         "thick_coin", "top", "toy_top"]


def cases() -> dict[str, list[list[str]]]:
    """name -> args, grouped by command."""
    out: dict[str, dict[str, list[str]]] = {}

    def add(cmd: str, name: str, *args: str) -> None:
        out.setdefault(cmd, {})[name] = [cmd, *args]

    for ex in EXAMPLES:
        f = f"examples/{ex}.yaml"
        add("inertia", ex, f)
        add("inertia", f"{ex}-json", f, "--json")
        add("principal", ex, f)
        add("principal", f"{ex}-json", f, "--json")
        add("balance", ex, f)
        add("balance", f"{ex}-json", f, "--json")
        add("precess", ex, f, "--omega", "0.3,1,0.2")
        add("precess", f"{ex}-json", f, "--omega", "0.3,1,0.2", "--json")
    for ex in ROUND:
        f = f"examples/{ex}.yaml"
        add("rollcheck", ex, f)
        add("rollcheck", f"{ex}-json", f, "--json")
        add("rollcheck", f"{ex}-speed", f, "--speed", "3 m/s")
        add("rollcheck", f"{ex}-speed-json", f, "--speed", "3 m/s", "--json")
        add("top", ex, f, "--spin", "150", "--theta", "30")
        add("top", f"{ex}-json", f, "--spin", "150", "--theta", "30", "--json")
    # the documented command lines (README and man pages)
    add("inertia", "lamina-axis", "examples/square_lamina.yaml", "--axis", "1,1,0")
    add("inertia", "lamina-omega", "examples/square_lamina.yaml", "--omega", "1,0,0")
    add("inertia", "lamina-about-omega-json", "examples/square_lamina.yaml", "--about", "1,1,0",
        "--omega", "0,0,300 rpm", "--axis", "z", "--json")
    add("inertia", "bracket-units", "examples/bracket.yaml", "--units", "in,lb")
    # bare numbers follow the body's units (issue 13): inches, and mm with rpm
    add("inertia", "bracket-about-bare", "examples/bracket.yaml", "--about", "0.5,0.5,0", "--units", "in,lb")
    add("balance", "rotor_mm-bare", "examples/rotor_mm.yaml", "--radius", "180", "--planes=-50,50",
        "--speed", "3000")
    add("balance", "rotor_mm-bare-json", "examples/rotor_mm.yaml", "--radius", "180", "--planes=-50,50",
        "--speed", "3000", "--json")
    add("balance", "rotor_mm-far", "examples/rotor_mm.yaml", "--radius", "180 m", "--planes=-50,50 m",
        "--speed", "3000 rad/s")
    add("inertia", "bracket-positive", "examples/bracket.yaml", "--products", "positive", "--digits", "4")
    add("inertia", "housing-axis", "examples/housing.yaml", "--axis", "z")
    add("inertia", "expr-json", "-e", "{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}", "--json")
    add("inertia", "many-json", "examples/cube.yaml", "examples/square_lamina.yaml", "--json")
    add("inertia", "many", "examples/cube.yaml", "examples/square_lamina.yaml")
    add("inertia", "error-about", "examples/cube.yaml", "--about", "1,2")
    add("inertia", "error-missing", "examples/nope.yaml")
    add("principal", "lamina-origin", "examples/square_lamina.yaml", "--about", "origin")
    add("principal", "expr", "-e", "{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}")
    add("balance", "wheel-planes", "examples/car_wheel.yaml", "--planes=-100,100mm", "--speed",
        "1500 rpm", "--bearings=-50,150mm")
    add("balance", "wheel-grade", "examples/car_wheel.yaml", "--planes=-100,100mm", "--speed",
        "1500 rpm", "--bearings=-50,150mm", "--grade", "G40", "--mass-step", "5 g")
    add("balance", "wheel-grade-json", "examples/car_wheel.yaml", "--planes=-100,100mm", "--speed",
        "1500 rpm", "--bearings=-50,150mm", "--grade", "G40", "--mass-step", "5 g", "--json")
    add("balance", "fan-grade", "examples/fan_impeller.yaml", "--bearings", "0,200mm", "--speed",
        "1480 rpm", "--grade", "G6.3")
    add("balance", "fan-positions", "examples/fan_impeller.yaml", "--planes", "320,380mm", "--radius",
        "190mm", "--bearings", "0,200mm", "--speed", "1480 rpm", "--grade", "G6.3", "--positions", "6",
        "--mass-step", "0.5 g")
    add("balance", "fan-positions-json", "examples/fan_impeller.yaml", "--planes", "320,380mm",
        "--radius", "190mm", "--bearings", "0,200mm", "--speed", "1480 rpm", "--grade", "G6.3",
        "--positions", "6", "--mass-step", "0.5 g", "--json")
    add("balance", "rotor-grade", "examples/two_disk_rotor.yaml", "--planes", "0,400mm", "--radius",
        "100mm", "--speed", "3000 rpm", "--bearings", "0,400mm", "--grade", "G6.3")
    add("balance", "rotor-grade-json", "examples/two_disk_rotor.yaml", "--planes", "0,400mm",
        "--radius", "100mm", "--speed", "3000 rpm", "--bearings", "0,400mm", "--grade", "G6.3", "--json")
    add("balance", "rotor-against", "examples/two_disk_rotor.yaml", "--planes", "0,400mm", "--radius",
        "100mm", "--angle-sense", "against", "--zero-mark-deg", "30", "--angle-step", "15",
        "--tolerance-planes", "corrections", "--grade", "G2.5", "--speed", "3000 rpm", "--units", "mm,kg")
    add("balance", "error-radius", "examples/two_disk_rotor.yaml", "--radius", "100mm")
    add("field-balance", "one-plane", "--initial", "6.0@30", "--trial", "10 g@0", "--run", "4.0@110")
    add("field-balance", "one-plane-json", "--initial", "6.0@30", "--trial", "10 g@0", "--run",
        "4.0@110", "--json")
    add("field-balance", "two-plane", "--initial", "170@112,53@78", "--trial", "1.15 g@0", "--run",
        "235@94,58@68", "--trial", "1.15 g@0", "--run", "185@115,77@104")
    add("field-balance", "two-plane-json", "--initial", "170@112,53@78", "--trial", "1.15 g@0",
        "--run", "235@94,58@68", "--trial", "1.15 g@0", "--run", "185@115,77@104", "--json")
    add("field-balance", "units-displacement", "--initial", "6 mm@30", "--trial", "10 g@0", "--run",
        "4000 um@110")
    add("field-balance", "units-velocity-json", "--initial", "0.25 in/s@30", "--trial", "10@0",
        "--run", "4.0 mm/s@110", "--json")
    add("field-balance", "error-mixed-units", "--initial", "6 mm@30", "--trial", "10 g@0", "--run",
        "4.0 mm/s@110")
    # field-balance beyond one reading per plane (issue 25): a job file, least squares,
    # min-max, a trial mass sized, display units
    goodman = ["--initial", "1@0,1@180,0@0", "--trial", "1@0", "--run", "4@0,4@0,5@0", "--trial", "1@0",
               "--run", "1@180,3@180,3@180"]
    add("field-balance", "job-fan", "examples/jobs/fan.yaml")
    add("field-balance", "job-fan-json", "examples/jobs/fan.yaml", "--json")
    add("field-balance", "goodman-least-squares", *goodman)
    add("field-balance", "goodman-least-squares-json", *goodman, "--json")
    add("field-balance", "goodman-min-max", *goodman, "--method", "min-max")
    add("field-balance", "suggest-trial", "--suggest-trial", "--rotor-mass", "120 kg", "--speed",
        "1480 rpm", "--trial-radius", "250 mm")
    add("field-balance", "units-in-oz", "--initial", "2 mil@30", "--trial", "1 oz@0", "--run",
        "1.5 mil@110", "--units", "in,oz")
    add("field-balance", "error-measure-mix", "--initial", "6 mm/s rms@30", "--trial", "10 g@0",
        "--run", "4 mm/s@110")
    # the shop's limits, a drawer and a bad reading (issue 36)
    add("field-balance", "job-fan-drawer", "examples/jobs/fan-drawer.yaml")
    add("field-balance", "job-fan-drawer-json", "examples/jobs/fan-drawer.yaml", "--json")
    add("field-balance", "goodman-limits", *goodman, "--method", "min-max", "--max-mass", "0.9 g,2 g",
        "--limit", "1=0.5")
    add("field-balance", "robust", "--initial", "1@0,1@180,0@0,2@90,9@45", "--trial", "1 g@0", "--run",
        "4@0,4@0,5@0,1@0,9@45", "--trial", "1 g@0", "--run", "1@180,3@180,3@180,2@0,9@40", "--robust", "huber")
    add("field-balance", "error-drawer-no-holes", *goodman, "--drawer", "1 g:4")
    add("precess", "book", "examples/book.yaml", "--omega", "0.01,1,0.01")
    add("precess", "book-at-json", "examples/book.yaml", "--omega", "0.01,1,0.01", "--at", "1e9", "--json")
    add("precess", "earth", "examples/earth.yaml", "--omega", "7.292115858e-11,0,7.292115858e-5 rad/s")
    add("precess", "frisbee", "examples/frisbee.yaml", "--omega", "0.8715574275,0,9.961946981")
    add("precess", "frisbee-json", "examples/frisbee.yaml", "--omega", "0.8715574275,0,9.961946981", "--json")
    add("precess", "football-csv", "examples/football.yaml", "--omega", "1.73648,0,9.84808",
        "--duration", "5", "--samples", "21", "--csv", "-")
    add("top", "sheet", "examples/top.yaml", "--spin", "150", "--theta", "30", "--g", "9.81")
    add("top", "sheet-json", "examples/top.yaml", "--spin", "150", "--theta", "30", "--g", "9.81", "--json")
    add("top", "gyro-horizontal", "examples/gyroscope.yaml", "--spin", "3000 rpm", "--theta", "90")
    add("top", "phidot", "examples/top.yaml", "--spin", "150", "--theta", "30", "--phi-dot", "10")
    add("top", "csv", "examples/top.yaml", "--spin", "150", "--theta", "30", "--csv", "-", "--samples", "5")
    add("top", "verify-json", "examples/top.yaml", "--spin", "150", "--theta", "30", "--verify", "--json")
    add("top", "sleeping", "examples/top.yaml", "--spin", "1000", "--theta", "0.5")
    add("top", "error-samples-without-csv", "examples/top.yaml", "--spin", "150", "--theta", "30",
        "--samples", "50")
    add("precess", "error-samples-without-csv", "examples/book.yaml", "--omega", "0.01,1,0.01",
        "--samples", "50")
    add("gyrocompass", "ratio", "--ratio", "2", "--spin", "6000 rpm", "--latitude", "30")
    add("gyrocompass", "ratio-json", "--ratio", "2", "--spin", "20000 rpm", "--latitude", "45", "--json")
    add("gyrocompass", "expr", "-e", "{shape: disk, radius: 0.1, mass: 1}", "--spin", "6000 rpm",
        "--latitude", "30")
    add("gyrocompass", "gyroscope-json", "examples/gyroscope.yaml", "--spin", "6000 rpm", "--latitude",
        "30", "--json")
    add("rollcheck", "bicycle-5kmh", "examples/bicycle_wheel.yaml", "--speed", "5 km/h")
    add("rollcheck", "hoop-circle", "examples/hoop.yaml", "--lean", "20", "--circle", "2")
    add("rollcheck", "hoop-circle-json", "examples/hoop.yaml", "--lean", "20", "--circle", "1", "--json")
    add("rollcheck", "penny-json", "examples/penny.yaml", "--speed", "0.1", "--json")
    add("rollcheck", "coin-tyre", "examples/thick_coin.yaml", "--tyre-radius", "1 mm", "--speed", "1")
    # --format csv (the tables for spreadsheets) and the robot descriptions
    add("inertia", "bracket-csv", "examples/bracket.yaml", "--format", "csv")
    add("inertia", "many-csv", "examples/cube.yaml", "examples/square_lamina.yaml", "--format", "csv")
    add("inertia", "bracket-urdf", "examples/bracket.yaml", "--format", "urdf")
    add("inertia", "fan-sdf-principal", "examples/two_blade_fan.yaml", "--format", "sdf", "--principal")
    add("inertia", "fan-mjcf", "examples/two_blade_fan.yaml", "--format", "mjcf")
    add("inertia", "error-urdf-positive", "examples/bracket.yaml", "--format", "urdf", "--products", "positive")
    add("inertia", "fan-mjcf-principal", "examples/two_blade_fan.yaml", "--format", "mjcf", "--principal")
    add("principal", "fan-csv", "examples/two_blade_fan.yaml", "--format", "csv")
    add("balance", "rotor-grade-csv", "examples/two_disk_rotor.yaml", "--planes", "0,400mm", "--radius",
        "100mm", "--speed", "3000 rpm", "--bearings", "0,400mm", "--grade", "G6.3", "--format", "csv")
    add("field-balance", "two-plane-csv", "--initial", "170@112,53@78", "--trial", "1.15 g@0", "--run",
        "235@94,58@68", "--trial", "1.15 g@0", "--run", "185@115,77@104", "--format", "csv")
    add("precess", "book-csv", "examples/book.yaml", "--omega", "0.01,1,0.01", "--format", "csv")
    add("rollcheck", "bicycle-csv", "examples/bicycle_wheel.yaml", "--speed", "5 km/h", "--format", "csv")
    add("top", "sheet-csv", "examples/top.yaml", "--spin", "150", "--theta", "30", "--g", "9.81", "--format", "csv")
    add("gyrocompass", "gyroscope-csv", "examples/gyroscope.yaml", "--spin", "6000 rpm", "--latitude", "30",
        "--format", "csv")
    add("principal", "fan-csv-digits", "examples/two_blade_fan.yaml", "--format", "csv", "--digits", "17")
    add("rollcheck", "error-format", "examples/penny.yaml", "--format", "xml")
    # whirl (issue 26): the physics sheet's worked examples, the README's fan, bad input
    cyl = "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}"
    disk = "{shape: cylinder, radius: 0.3, length: 0.05, mass: 100}"
    fan = ["examples/fan_rotor.yaml", "--bearings", "0,500mm", "--stiffness", "5 N/um", "--damping",
           "1 N*s/mm", "--speed", "1480 rpm", "--speed-range", "0,3000 rpm", "--orders", "1,2"]
    add("whirl", "sheet-cylinder", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6")
    add("whirl", "sheet-cylinder-json", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6",
        "--points", "11", "--json")
    add("whirl", "sheet-disk", "-e", disk, "--bearings=-0.1,0.1", "--stiffness", "2e6", "--orders", "1,2")
    add("whirl", "fan", *fan)
    add("whirl", "fan-json", *fan, "--points", "31", "--json")
    add("whirl", "fan-csv", *fan, "--format", "csv")
    add("whirl", "fan-fail", *fan[:-6], "--speed", "1800 rpm")
    add("whirl", "fan-anisotropic-planes", "examples/fan_rotor.yaml", "--bearings", "0,500", "--stiffness",
        "5e6,4e6", "--stiffness-y", "8e6", "--damping", "800", "--speed", "1200,1600 rpm", "--unbalance",
        "50 g*mm@0,30 g*mm@120", "--unbalance-planes", "710,800", "--units", "mm,kg")
    add("whirl", "unstable", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6", "--cross-stiffness",
        "1e5", "--damping", "100", "--speed", "150")
    add("whirl", "error-one-bearing", "-e", cyl, "--bearings", "0.1", "--stiffness", "1e6")
    add("whirl", "error-one-place", "-e", cyl, "--bearings", "0.1,0.1", "--stiffness", "1e6")
    add("whirl", "error-negative-stiffness", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness=-1e6")
    add("whirl", "error-empty-range", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6",
        "--speed-range", "1000,1000 rpm")
    add("whirl", "error-not-a-range", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6",
        "--speed-range", "3000,0 rpm")
    # whirl (issue 35): bearings in the body file, tables against speed, cross-coupling, the map
    journal = "examples/journal_rotor.yaml"
    add("whirl", "journal", journal)
    add("whirl", "journal-json", journal, "--points", "21", "--json")
    add("whirl", "journal-unstable", journal, "--speed", "8500 rpm")
    add("whirl", "journal-options-over-table", journal, "--cross-stiffness", "0", "--speed", "3000 rpm",
        "--points", "41")
    add("whirl", "cross-coupled-1", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6", "--damping",
        "200", "--cross-stiffness", "1")
    add("whirl", "full-2x2", "-e", cyl, "--bearings=-0.2,0.2", "--stiffness", "1e6,1.2e6", "--stiffness-y",
        "1.5e6", "--stiffness-xy", "2e5", "--stiffness-yx=-1.5e5", "--damping", "400", "--damping-xy", "50",
        "--damping-yx", "50", "--map-stiffness", "1e5,1e7", "--points", "41")
    add("whirl", "error-beyond-table", journal, "--speed", "12000 rpm")
    add("shapes", "all")
    add("shapes", "cylinder", "cylinder")
    add("shapes", "mesh", "mesh")
    add("shapes", "step", "step")
    add("materials", "steel", "steel")
    add("materials", "peek-json", "PEEK", "--json")
    add("materials", "error-none", "unobtainium")
    add("inertia", "error-material", "-e", "{shape: box, size: [1, 1, 1], material: stell}")
    add("inertia", "error-material-option", "examples/cube.yaml", "--material", "steel")
    add("examples", "list")
    return {cmd: [[n, *a] for n, a in d.items()] for cmd, d in out.items()}


def run(args: list[str]) -> tuple[int, str, str]:
    """Run rbcli in-process as a script would: not a terminal, no colour, 100 columns."""
    from conftest import run_inprocess

    r = run_inprocess(*args)
    return r.code, r.out, r.err


def main() -> None:
    import json

    new_only = "--new-only" in sys.argv
    for cmd, items in cases().items():
        d = HERE / cmd
        d.mkdir(exist_ok=True)
        for name, *args in items:
            case = d / f"{name}.yaml"
            if new_only and case.exists():
                continue
            code, out, err = run(args)
            case.write_text(f"args: {json.dumps(args)}\nexit: {code}\n", encoding="utf-8")
            (d / f"{name}.out").write_text(out, encoding="utf-8")
            (d / f"{name}.err").write_text(err, encoding="utf-8")
            print(f"{cmd}/{name}: exit {code}")


if __name__ == "__main__":
    main()
