"""The bad-input sweep's table: each case makes a bad input from a shipped one (an
edited copy of a dictionary or CSV, or a bad option) and says what the tool's
message must name (the file and the entry, option or CSV column). `kind` is
"error" (non-zero exit) or "warning" (a legal value that looks like a unit
mix-up: exit 0, a warning naming the entry; counted apart).

A case: Case(tool, name, files, argv, needles, kind). `files` maps a path in
the case's scratch folder to a function of the project root giving its text
(or bytes), or to None for a folder; `argv` and `needles` are lists in which
"{root}" stands for the project root.
"""

import os
from dataclasses import dataclass, field

import edits as e


@dataclass
class Case:
    tool: str
    name: str
    files: dict
    argv: list
    needles: list
    kind: str = "error"
    env: dict = field(default_factory=dict)

    @property
    def id(self):
        return "%s-%s-%s" % (self.kind, self.tool, self.name)


def read(rel, binary=False):
    def text(root):
        with open(os.path.join(root, rel), "rb" if binary else "r") as f:
            return f.read()
    return text


def edited(rel, fn):
    return lambda root: fn(read(rel)(root))


CASES = []


def add(*a, **k):
    CASES.append(Case(*a, **k))


# ----------------------------------------------------------------------------- drumSolver
INVICTA = "cases/invictaDryer/drumDict"
PHYSICS = "cases/invictaDryer/physics/drumDict"
TWOPHASE = "cases/invictaDryer/physics/twoPhase/drumDict"
NUMERIC = {  # entry -> a value outside its range
    "drum.length": "-5", "drum.diameter": "50", "drum.slope_deg": "-3", "drum.speed_rpm": "100",
    "flights.count": "1", "flights.baseLength": "4", "flights.tipLength": "-0.1",
    "flights.baseAngle_deg": "10", "flights.tipAngle_deg": "200", "material.feedRate": "-2",
    "material.bulkDensity": "3e4", "material.particleDensity": "500", "model.slices": "0",
    "model.kilnTime": "1e300", "model.backFraction": "1.5", "model.forwardDragFactor": "-1",
    "rtd.timeStep": "-1", "rtd.recovery": "1.5", "rtd.pulseDuration": "-4", "gas.massRate": "-1",
}
for entry, out in NUMERIC.items():
    key = entry.split(".")[-1]
    for label, value, needle in (("notNumber", "abc", entry), ("range", out, entry), ("nan", ".nan", entry),
                                 ("inf", "1e400", entry), ("empty", "", entry)):
        add("drumSolver", "%s-%s" % (entry, label),
            {"c/drumDict": edited(INVICTA, lambda t, en=entry, v=value: e.yaml_set(t, en, v))},
            ["drumSolver", "-case", "c"], ["c/drumDict", needle])
    add("drumSolver", "%s-misspelt" % entry,
        {"c/drumDict": edited(INVICTA, lambda t, en=entry, k=key: e.yaml_rename(t, en, k + "x"))},
        ["drumSolver", "-case", "c"], ["c/drumDict", key + "x"])
    add("drumSolver", "%s-twice" % entry,
        {"c/drumDict": edited(INVICTA, lambda t, en=entry: e.yaml_duplicate(t, en))},
        ["drumSolver", "-case", "c"], ["c/drumDict", key])
for entry in ("drum.length", "drum.diameter", "drum.speed_rpm", "flights.count", "material.feedRate",
              "material.bulkDensity", "material.sizes_um", "model.type"):
    add("drumSolver", "%s-missing" % entry,
        {"c/drumDict": edited(INVICTA, lambda t, en=entry: e.yaml_remove(t, en))},
        ["drumSolver", "-case", "c"], ["c/drumDict", entry.split(".")[-1]])
for name, entry, value, needle in (
        ("timeStep1e5", "rtd.timeStep", "1e5", "rtd.timeStep"),
        ("timeStep1000", "rtd.timeStep", "1000", "rtd.timeStep"),
        ("recoveryCutsTail", "rtd.recovery", "0.9", "rtd.recovery"),
        ("integratorWord", "rtd.integrator", "rk4", "rtd.integrator"),
        ("EColumn", "rtd.tracer.EColumn", "E_perh", "rtd.tracer.EColumn"),
        ("timeColumn", "rtd.tracer.timeColumn", "t_s", "rtd.tracer.timeColumn"),
        ("EUnit", "rtd.tracer.EUnit", "per_day", "rtd.tracer.EUnit"),
        ("tracerMissing", "rtd.tracer.file", "absent.csv", "rtd.tracer.file"),
        ("tracerFolder", "rtd.tracer.file", "tdir", "tdir"),
        ("modelType", "model.type", "compartmnt", "model.type"),
        ("partition", "model.partition", "lee", "model.partition"),
        ("gasFlow", "gas.flow", "sideways", "gas.flow"),
        ("sizesNotList", "material.sizes_um", "850", "material.sizes_um"),
        ("sizesWord", "material.sizes_um", "[abc]", "material.sizes_um"),
        ("sizesRange", "material.sizes_um", "[2e5]", "material.sizes_um"),
        ("fractionsShort", "material.fractions_pct", "[50, 50]", "material.fractions_pct"),
        ("fractionsNegative", "material.fractions_pct", "[-100]", "material.fractions_pct"),
        ("moistureRange", "material.moisture", "{inlet: 2, outlet: 0.002}", "material.moisture.inlet"),
        ("moistureKey", "material.moisture", "{inlet: 0.02, outlt: 0.002}", "outlt")):
    files = {"c/drumDict": edited(INVICTA, lambda t, en=entry, v=value: e.yaml_set(t, en, v))}
    if name == "tracerFolder":
        files["c/tdir"] = None
    add("drumSolver", name, files, ["drumSolver", "-case", "c"], ["c/drumDict" if name != "tracerFolder"
                                                                   else "c/tdir", needle])
for name, entry, value in (("driftWord", "model.drift", "cfd"), ("tableMissing", "drift.table", "absent.csv"),
                           ("outsideWord", "drift.outside", "sometimes"), ("holdupWord", "model.flightHoldup", "full"),
                           ("pickupRange", "model.flightPickup_deg", "200"), ("slopeWord", "model.kilnBedSlope_deg", "steep")):
    fn = (lambda t, en=entry, v=value: e.yaml_set(t, en, v)) if entry.split(".")[-1] in (
        "drift", "table", "flightHoldup", "kilnBedSlope_deg") else \
        (lambda t, en=entry, v=value: t.replace("\ndrift:\n", "\ndrift:\n  %s: %s\n" % (en.split(".")[1], v), 1)
         if en.startswith("drift.") else t.replace("  flightHoldup: bedFilled", "  flightHoldup: bedFilled\n  %s: %s"
                                                   % (en.split(".")[1], v), 1))
    add("drumSolver", "physics-" + name, {"c/drumDict": edited(PHYSICS, fn)}, ["drumSolver", "-case", "c"],
        ["c/drumDict", entry.split(".")[-1]])
for entry, value in (("model.denseDispersion", "abc"), ("model.type", "twoPhaze"), ("drum.slope_deg", "45"), ("model.drift", "magic")):
    add("drumSolver", "twoPhase-%s" % entry, {"c/drumDict": edited(TWOPHASE, lambda t, en=entry, v=value: e.yaml_set(t, en, v))},
        ["drumSolver", "-case", "c"], ["c/drumDict", entry])
add("drumSolver", "dictFolder", {"c/drumDict": None}, ["drumSolver", "-case", "c"], ["c/drumDict", "folder"])
add("drumSolver", "dictMissing", {"c/x": lambda r: "x"}, ["drumSolver", "-case", "c"], ["c/drumDict"])
add("drumSolver", "yamlSyntax", {"c/drumDict": edited(INVICTA, lambda t: t.replace("drum:\n", "drum: [\n", 1))},
    ["drumSolver", "-case", "c"], ["c/drumDict", "YAML"])
add("drumSolver", "tabs", {"c/drumDict": edited(INVICTA, lambda t: t.replace("  length: 12", "\tlength: 12", 1))},
    ["drumSolver", "-case", "c"], ["c/drumDict"])
add("drumSolver", "binary", {"c/drumDict": lambda r: b"\x00\x01\xff\xfe" * 64}, ["drumSolver", "-case", "c"],
    ["c/drumDict"])
add("drumSolver", "unknownTop", {"c/drumDict": edited(INVICTA, lambda t: t + "\nextras:\n  a: 1\n")},
    ["drumSolver", "-case", "c"], ["c/drumDict", "extras"])
add("drumSolver", "caseTwice", {"c/drumDict": read(INVICTA), "d/drumDict": read(INVICTA)},
    ["drumSolver", "-case", "c", "-case", "d"], ["-case", "twice"])
add("drumSolver", "caseNoValue", {}, ["drumSolver", "-case"], ["-case"])
add("drumSolver", "unknownOption", {}, ["drumSolver", "-cas", "c"], ["-cas"])
add("drumSolver", "resultsIsFile", {"c/drumDict": read(INVICTA), "c/results": lambda r: "mine"},
    ["drumSolver", "-case", "c"], ["c/results"])
for entry, value in (("drum.speed_rpm", "0.05"), ("material.bulkDensity", "0.94"),
                     ("material.sizes_um", "[850e-6]")):
    add("drumSolver", "unit-" + entry, {"c/drumDict": edited(INVICTA, lambda t, en=entry, v=value: e.yaml_set(t, en, v))},
        ["drumSolver", "-case", "c"], ["c/drumDict", entry, "warning"], kind="warning")
add("drumSolver", "unit-gas.temperature_C",
    {"c/drumDict": edited(INVICTA, lambda t: e.yaml_set(t, "gas.massRate", "0\n  temperature_C: 353.15"))},
    ["drumSolver", "-case", "c"], ["c/drumDict", "gas.temperature_C", "warning"], kind="warning")

# ----------------------------------------------------------------------------- windTunnelDrift
TESTS = "data/windtunnel_tests.csv"
MATS = "data/windtunnel_materials.csv"
for column, out in (("air_velocity_m_s", "95"), ("spill_rate_kg_m_s", "-1"), ("flight_length_m", "0"),
                    ("fall_height_m", "500"), ("test", "11.5"), ("material", "rawShale")):
    for label, value in (("notNumber", "abc"), ("empty", ""), ("range", out), ("nan", "nan"), ("inf", "inf")):
        if column == "material" and label != "range":
            continue
        add("windTunnelDrift", "tests-%s-%s" % (column, label),
            {"t.csv": edited(TESTS, lambda t, c=column, v=value: e.csv_set(t, 3, c, v))},
            ["windTunnelDrift", "-tests", "t.csv", "-model", "sherritt", "-out", "p.csv"],
            ["t.csv", "line 4" if column not in ("air_velocity_m_s", "spill_rate_kg_m_s", "flight_length_m",
                                                 "fall_height_m") or label in ("notNumber", "empty", "nan", "inf")
             else "test ", column if label != "range" or column in ("test", "material") else column])
    add("windTunnelDrift", "tests-%s-noColumn" % column,
        {"t.csv": edited(TESTS, lambda t, c=column: e.csv_rename_column(t, c, c + "x"))},
        ["windTunnelDrift", "-tests", "t.csv", "-model", "sherritt", "-out", "p.csv"], ["t.csv", column])
add("windTunnelDrift", "tests-duplicateId",
    {"t.csv": edited(TESTS, lambda t: "\n".join(t.split("\n")[:3] + t.split("\n")[2:3] + t.split("\n")[3:]))},
    ["windTunnelDrift", "-tests", "t.csv", "-model", "sherritt", "-out", "p.csv"], ["t.csv", "test 12", "twice"])
add("windTunnelDrift", "tests-empty", {"t.csv": edited(TESTS, lambda t: t.split("\n")[0] + "\n")},
    ["windTunnelDrift", "-tests", "t.csv", "-model", "sherritt", "-out", "p.csv"], ["t.csv", "no test rows"])
for column, value in (("particle_density_kg_m3", "abc"), ("particle_density_kg_m3", "5"), ("sphericity", "2"),
                      ("psd_wt_pct", "-3"), ("psd_wt_pct", "x"), ("psd_lower_um", "abc"), ("material", "")):
    add("windTunnelDrift", "materials-%s-%s" % (column, value or "empty"),
        {"m.csv": edited(MATS, lambda t, c=column, v=value: e.csv_set(t, 2, c, v))},
        ["windTunnelDrift", "-tests", "{root}/" + TESTS, "-materials", "m.csv", "-model", "sherritt", "-out", "p.csv"],
        ["m.csv", column])
for name, extra, needle in (
        ("model", ["-model", "magic"], "-model"), ("outside", ["-model", "table", "-outside", "sometimes"], "-outside"),
        ("jobs", ["-model", "cfd", "-jobs", "0"], "-jobs"), ("gasPressure", ["-model", "sherritt", "-gasPressure", "5"], "-gasPressure"),
        ("gasPressureWord", ["-model", "sherritt", "-gasPressure", "high"], "-gasPressure"),
        ("level", ["-model", "cfd", "-level", "ultra"], "-level"), ("quantity", ["-model", "sherritt", "-quantity", "vc"], "-quantity"),
        ("sieveBottom", ["-model", "sherritt", "-sieveBottom", "100"], "-sieveBottom"),
        ("tableMissing", ["-model", "table", "-table", "absent.csv"], "absent.csv"),
        ("tableFolder", ["-model", "table", "-table", "tdir"], "tdir"),
        ("testsFolder", ["-model", "sherritt", "-tests", "tdir"], "tdir"),
        ("modelTwice", ["-model", "sherritt", "-model", "isolated"], "given twice"),
        ("unknown", ["-model", "sherritt", "-colour", "red"], "-colour"),
        ("noValue", ["-model"], "-model"), ("segmentVc", ["-model", "segmentVc"], "segmentVc"),
        ("turbulence", ["-model", "cfd", "-turbulence", "laminar"], "-turbulence"),
        ("layer", ["-model", "cfd", "-layerThickness", "thick"], "-layerThickness"),
        ("wakeShare", ["-model", "cfd", "-wakeShare", "0.5"], "-wakeShare"),
        ("constants", ["-model", "porousSheet", "-constants", "absent.yaml"], "absent.yaml"),
        ("outFolder", ["-model", "sherritt", "-out", "tdir"], "tdir")):
    argv = ["windTunnelDrift"] + ([] if "-tests" in extra else ["-tests", "{root}/" + TESTS]) + extra
    if "-out" not in extra:
        argv += ["-out", "p.csv"]
    add("windTunnelDrift", "option-" + name, {"tdir": None}, argv, [needle])
SHERRITT_PRED = "validation/windTunnelDrift/results/predictions/sherritt.csv"
for name, fn, needles in (
        ("twice", lambda t: t + t.split("\n")[1] + "\n", ["p.csv", "twice"]),
        ("unknown", lambda t: t + "9999,1.5\n", ["p.csv", "9999"]),
        ("missing", lambda t: "\n".join(t.split("\n")[:1] + t.split("\n")[2:]), ["p.csv", "-allowMissing"]),
        ("notNumber", lambda t: e.csv_set(t, 2, "mean_advance_m", "abc"), ["p.csv", "mean_advance_m"]),
        ("noColumn", lambda t: e.csv_rename_column(t, "mean_advance_m", "advance"), ["p.csv", "mean_advance_m"]),
        ("empty", lambda t: t.split("\n")[0] + "\n", ["p.csv", "no predictions"])):
    add("windTunnelDrift", "score-" + name, {"p.csv": edited(SHERRITT_PRED, fn)},
        ["windTunnelDrift", "-score", "-tests", "{root}/" + TESTS, "-predictions", "s=p.csv", "-out", "s.csv"], needles)
add("windTunnelDrift", "score-notNameFile", {}, ["windTunnelDrift", "-score", "-tests", "{root}/" + TESTS,
                                                 "-predictions", "p.csv", "-out", "s.csv"], ["-predictions", "NAME=FILE"])
add("windTunnelDrift", "score-pngModels", {"p.csv": read(SHERRITT_PRED)},
    ["windTunnelDrift", "-score", "-tests", "{root}/" + TESTS, "-predictions", "s=p.csv", "-out", "s.csv",
     "-pngModels", "s"], ["-pngModels"])

# ----------------------------------------------------------------------------- flightUnloading, drumSegmentMesh
FLIGHTS = "applications/utilities/flightUnloading/invicta.yaml"
FLIGHT_ENTRIES = {"drum.radius": "-1", "drum.nFlights": "1", "drum.speed": "-3", "drum.slope": "60",
                  "flight.baseLength": "-0.1", "flight.tipLength": "9", "flight.baseAngle": "400",
                  "flight.tipAngle": "-5", "flight.length": "-12", "material.bulkDensity": "-1",
                  "material.dynamicAngleOfRepose": "95", "output.angleStep": "0", "output.snapshotAngle": "720"}
for entry, out in FLIGHT_ENTRIES.items():
    key = entry.split(".")[-1]
    for label, value in (("notNumber", "abc"), ("range", out), ("nan", ".nan"), ("empty", "")):
        add("flightUnloading", "%s-%s" % (entry, label),
            {"f.yaml": edited(FLIGHTS, lambda t, en=entry, v=value: e.yaml_set(t, en, v))},
            ["flightUnloading", "-dict", "f.yaml", "-out", "o"], ["f.yaml", entry])
    add("flightUnloading", "%s-misspelt" % entry,
        {"f.yaml": edited(FLIGHTS, lambda t, en=entry, k=key: e.yaml_rename(t, en, k + "x"))},
        ["flightUnloading", "-dict", "f.yaml", "-out", "o"], ["f.yaml", key + "x"])
    add("flightUnloading", "%s-twice" % entry,
        {"f.yaml": edited(FLIGHTS, lambda t, en=entry: e.yaml_duplicate(t, en))},
        ["flightUnloading", "-dict", "f.yaml", "-out", "o"], ["f.yaml", key])
for name, files, argv, needles in (
        ("dictFolder", {"f.yaml": None}, ["-dict", "f.yaml"], ["f.yaml", "folder"]),
        ("dictMissing", {}, ["-dict", "f.yaml"], ["f.yaml"]),
        ("dictTwice", {"f.yaml": read(FLIGHTS)}, ["-dict", "f.yaml", "-dict", "f.yaml"], ["-dict", "twice"]),
        ("unknown", {"f.yaml": read(FLIGHTS)}, ["-dict", "f.yaml", "-colour"], ["-colour"]),
        ("noValue", {}, ["-dict"], ["-dict"])):
    add("flightUnloading", name, files, ["flightUnloading"] + argv, needles)
for entry, value in (("drum.radius", "abc"), ("flight.tipLength", "9"), ("drum.nFlights", "1"),
                     ("material.dynamicAngleOfRepose", "95")):
    add("drumSegmentMesh", "%s-%s" % (entry, value),
        {"f.yaml": edited(FLIGHTS, lambda t, en=entry, v=value: e.yaml_set(t, en, v))},
        ["drumSegmentMesh", "-dict", "f.yaml", "-length", "1.133", "-out", "o"], ["f.yaml", entry])
for name, extra, needle in (
        ("lengthZero", ["-length", "0"], "-length"), ("lengthWord", ["-length", "abc"], "-length"),
        ("lengthNan", ["-length", "nan"], "-length"), ("lengthTwice", ["-length", "1", "-length", "2"], "twice"),
        ("lengthMissing", [], "-length"), ("level", ["-length", "1", "-level", "ultra"], "-level"),
        ("plate", ["-length", "1", "-plateThickness", "1"], "-plateThickness"),
        ("release", ["-length", "1", "-releaseWidth", "0.001"], "-releaseWidth"),
        ("releaseWord", ["-length", "1", "-releaseWidth", "wide"], "-releaseWidth"),
        ("unknown", ["-length", "1", "-colour", "red"], "-colour"),
        ("outHere", ["-length", "1", "-out", "."], "-out")):
    add("drumSegmentMesh", name, {"f.yaml": read(FLIGHTS)},
        ["drumSegmentMesh", "-dict", "f.yaml"] + extra + ([] if "-out" in extra else ["-out", "o"]), [needle])
add("drumSegmentMesh", "dictFolder", {"f.yaml": None}, ["drumSegmentMesh", "-dict", "f.yaml", "-length", "1", "-out", "o"],
    ["f.yaml", "folder"])

# ----------------------------------------------------------------------------- curtainCase -check
BOX = ["-dir", "r", "-gasVelocity", "3", "-spillRate", "2", "-fallHeight", "4", "-heights", "1,2",
       "-flightLength", "1", "-density", "1590", "-diameters", "300e-6,850e-6", "-fractions", "0.5,0.5"]


def box(**over):
    argv = list(BOX)
    extra = []
    for k, v in over.items():
        opt = "-" + k
        if opt in argv:
            argv[argv.index(opt) + 1] = v
        else:
            extra += [opt, v]
    return ["curtainCase"] + argv + extra + ["-check"]


for opt, out in (("gasVelocity", "51"), ("spillRate", "-1"), ("fallHeight", "200"), ("flightLength", "0"),
                 ("density", "5"), ("releaseVelocity", "9"), ("boxWidth", "50"), ("gasTemperature", "2000"),
                 ("gasPressure", "5"), ("sphericity", "2"), ("iterations", "3"), ("np", "0")):
    for label, value in (("notNumber", "abc"), ("range", out), ("nan", "nan"), ("inf", "inf"), ("empty", "")):
        add("curtainCase", "%s-%s" % (opt, label), {}, box(**{opt: value}), ["-" + opt])
for name, over, needle in (
        ("diametersWord", {"diameters": "a,b"}, "-diameters"), ("diametersRange", {"diameters": "-1e-3,1e-3"}, "-diameters"),
        ("fractionsCount", {"fractions": "1"}, "-fractions"), ("fractionsSum", {"fractions": "0.5,0.6"}, "-fractions"),
        ("heightsAbove", {"heights": "1,9"}, "-heights"), ("level", {"level": "ultra"}, "-level"),
        ("drag", {"drag": "Stokes"}, "-drag"), ("turbulence", {"turbulence": "laminar"}, "-turbulence"),
        ("particleTurbulence", {"particleTurbulence": "Lagrangian"}, "-particleTurbulence"),
        ("dispersion", {"turbulentDispersion": "random"}, "-turbulentDispersion"),
        ("ppDrag", {"particleParticleDrag": "Gidaspow"}, "-particleParticleDrag"),
        ("wakeShareAlone", {"wakeShare": "0.5"}, "-wakeShare"),
        ("layerWord", {"layerThickness": "thick"}, "-layerThickness"),
        ("layerRange", {"layerThickness": "1"}, "-layerThickness"),
        ("bulkAlone", {"bulkDensity": "900"}, "-bulkDensity"),
        ("templateMissing", {"template": "absent"}, "absent"),
        ("scene", {"scene": "drum"}, "-scene")):
    add("curtainCase", name, {}, box(**over), [needle])
add("curtainCase", "optionTwice", {}, box() + ["-spillRate", "3"], ["-spillRate", "twice"])
add("curtainCase", "unknown", {}, box() + ["-colour", "red"], ["-colour"])
add("curtainCase", "missingRequired", {}, ["curtainCase", "-dir", "r", "-gasVelocity", "3", "-check"], ["missing option"])
add("curtainCase", "noValue", {}, box() + ["-level"], ["-level"])
add("curtainCase", "dirIsFile", {"r": lambda root: "x"}, box(), ["-dir", "r"])
TEMPLATE = "etc/templates/curtain/windTunnel"


def template_with(rel, fn):
    """The template copied into the scratch folder as tpl/, one file edited."""
    files = {}
    for d, _, fs in os.walk(os.path.join(os.path.dirname(__file__), "..", "..", TEMPLATE)):
        for f in fs:
            r = os.path.relpath(os.path.join(d, f), os.path.join(os.path.dirname(__file__), "..", ".."))
            files["tpl/" + os.path.relpath(r, TEMPLATE)] = read(r, binary=True)
    files["tpl/" + rel] = edited(TEMPLATE + "/" + rel, fn)
    return files


for name, rel, fn, needles in (
        ("meshParameterWord", "system/meshParameters", lambda t: t.replace("H ", "H  tall; //", 1), ["meshParameters", "H"]),
        ("meshParameterGone", "system/meshParameters", lambda t: "\n".join(l for l in t.split("\n")
                                                                          if not l.strip().startswith("H ")), ["meshParameters", "H"]),
        ("templateNotText", "system/meshParameters", lambda t: (t + "\nx ").encode() + b"\xff;\n",
         ["meshParameters", "UTF-8"])):
    add("curtainCase", name, template_with(rel, fn), box(template="tpl"), needles)
add("curtainCase", "unit-gasTemperature", {}, box(gasTemperature="353.15"), ["-gasTemperature", "warning"],
    kind="warning")

# ----------------------------------------------------------------------------- buildDriftTable
SWEEP = "cases/driftTable/smallTableDict"
SWEEP_ENTRIES = {"level": ("ultra", None), "drag": ("Stokes", None), "gasTemperature": ("2000", "abc"),
                 "boxWidth": ("50", "abc"), "grid/gasVelocity": ("(1 51)", "(1 x)"), "grid/spillRate": ("(8 1)", "(a)"),
                 "grid/flightLength": ("(0)", "(x)"), "grid/particleDensity": ("(5)", "(x)"),
                 "grid/fallHeight": ("(0.5 1 2 400)", "(x)"), "grid/diameter": ("(-1e-3)", "(x)"),
                 "massFractions": ("(0.5 0.5 0.5)", "(x y z)"), "output": ("\"\"", "(1 2)")}
for entry, (bad, word) in SWEEP_ENTRIES.items():
    key = entry.split("/")[-1]
    cases = [("range", bad)] + ([("word", word)] if word else [])
    for label, value in cases:
        add("buildDriftTable", "%s-%s" % (entry, label),
            {"d/sweepDict": edited(SWEEP, lambda t, en=entry, v=value: e.foam_set(t, en, v))},
            # a level is checked by curtainCase -check, which -list skips; -slurm checks
            # every case, then writes the job scripts only (nothing runs)
            ["buildDriftTable", "-dict", "d/sweepDict", "-work", "w"] + (["-list"] if label == "word" and key != "level" else ["-slurm"]),
            ["sweepDict", key])
    add("buildDriftTable", "%s-misspelt" % entry,
        {"d/sweepDict": edited(SWEEP, lambda t, en=entry, k=key: e.foam_rename(t, en, k + "x"))},
        ["buildDriftTable", "-dict", "d/sweepDict", "-list"], ["sweepDict", key + "x"])
    add("buildDriftTable", "%s-twice" % entry,
        {"d/sweepDict": edited(SWEEP, lambda t, en=entry: e.foam_duplicate(t, en))},
        ["buildDriftTable", "-dict", "d/sweepDict", "-list"], ["sweepDict", key])
for entry in ("grid/gasVelocity", "grid/diameter", "massFractions", "grid/spillRate"):
    add("buildDriftTable", "%s-missing" % entry,
        {"d/sweepDict": edited(SWEEP, lambda t, en=entry: e.foam_remove(t, en))},
        ["buildDriftTable", "-dict", "d/sweepDict", "-list"], ["sweepDict", entry.split("/")[-1]])
for name, files, argv, needles in (
        ("nonUtf8", {"d/sweepDict": lambda root: read(SWEEP, True)(root) + b"\nx \xff\xfe;\n"}, [], ["sweepDict", "UTF-8"]),
        ("nul", {"d/sweepDict": lambda root: b"a 1;\n" + b"\x00" * 32}, [], ["sweepDict", "NUL"]),
        ("dictFolder", {"d/sweepDict": None}, [], ["sweepDict"]),
        ("dictMissing", {"d/x": lambda root: ""}, [], ["sweepDict"]),
        ("unbalanced", {"d/sweepDict": edited(SWEEP, lambda t: t.replace("grid\n{", "grid\n{{", 1))}, [], ["sweepDict"]),
        ("jobs", {"d/sweepDict": read(SWEEP)}, ["-jobs", "0"], ["-jobs"]),
        ("np", {"d/sweepDict": read(SWEEP)}, ["-np", "x"], ["-np"]),
        ("scheduler", {"d/sweepDict": read(SWEEP)}, ["-scheduler", "pbs"], ["-scheduler"]),
        ("dictTwice", {"d/sweepDict": read(SWEEP)}, ["-dict", "d/sweepDict"], ["-dict", "twice"]),
        ("unknown", {"d/sweepDict": read(SWEEP)}, ["-colour"], ["-colour"]),
        ("scene", {"d/sweepDict": edited(SWEEP, lambda t: t.replace("level ", "scene drum;\nlevel ", 1))}, [], ["scene"]),
        ("layerWord", {"d/sweepDict": edited(SWEEP, lambda t: t.replace("level ", "layerThickness thick;\nlevel ", 1))},
         [], ["layerThickness"]),
        ("floorsOutside", {"d/sweepDict": edited(SWEEP, lambda t: t.replace("level ", "floors (9);\nlevel ", 1))}, [],
         ["floors"])):
    add("buildDriftTable", name, files, ["buildDriftTable", "-dict", "d/sweepDict"] + argv + ["-list"], needles)
add("buildDriftTable", "unit-gasTemperature",
    {"d/sweepDict": edited(SWEEP, lambda t: e.foam_set(t, "gasTemperature", "353.15"))},
    ["buildDriftTable", "-dict", "d/sweepDict", "-list"], ["sweepDict", "gasTemperature", "warning"], kind="warning")
