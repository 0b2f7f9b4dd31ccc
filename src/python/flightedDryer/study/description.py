"""description: a dryer's description, a YAML file with the drum model's own sections
(drum, flights, material, gas; optionally model without its drift, and rtd with a
tracer), read by drumSolver as they are, and the study's section `study:`, read
here. Keys given twice or not known are refused naming the file and the line."""

import difflib
import os

import yaml

from .. import PROJECT, facts
from ..errors import InputError

DRUM_SECTIONS = ("drum", "flights", "material", "gas", "model", "rtd")
STUDY_KEYS = {
    # key: (default, check, meaning for the report)
    "scene": ("box", ("box", "drumSegment"), "curtain scene: a box as wide as the drum (drumSegment: the drum's "
              "own cross-section, every flight's curtain at once)"),
    "level": ("coarse", ("coarse", "medium", "fine"), "curtain mesh level"),
    # (the drag laws are the C++ side's: facts.drag_laws, asked when a description is read)
    "drag": ("SchillerNaumann", "dragLaws", "the particles' drag law in the curtain runs"),
    "stop": ("statistical", ("statistical", "fixed"), "a drum segment's stop: when its means are known "
             "(statistical) or after its local steps, the last third's means (fixed)"),
    "iterations": (300, (30, 100000), "curtain iterations per run (the steady stop comes first)"),
    "margin": (0.25, (0.0, 2.0), "share the table's grid reaches beyond the drum model's queries"),
    "table": (None, None, "a drift table to use instead of sweeping one"),
    "fallStep": (1.0, (0.05, 10.0), "m between the table's fall heights (each a floor)"),
    "spillRatio": (3.0, (1.5, 100.0), "largest ratio of neighbouring spill rates of the table's grid"),
    "confirmAbove_s": (1800.0, (0.0, 1e7), "planned CPU time above which -yes is needed"),
    "curve": (None, None, "an operating curve: one input of the drum model over a list of values"),
}
# the inputs an operating curve may vary (section.key of the drum model's sections)
CURVE_ENTRIES = ("gas.massRate", "gas.temperature_C", "material.feedRate", "drum.speed_rpm", "drum.slope_deg",
                 "flights.count")
# the compartment model the study runs when the description names none: Lee's
# network from the flight geometry, as cases/invictaDryer/physics
COMPARTMENT_DEFAULTS = [("type", "compartment"), ("slices", 20), ("partition", "flightModel"),
                        ("sizeClasses", "resolved"), ("flightHoldup", "bedFilled"), ("kilnTime", "saeman"),
                        ("kilnBedSlope_deg", "profile")]
RTD_DEFAULTS = [("integrator", "exact"), ("timeStep", 5), ("recovery", 0.999)]


class StrictLoader(yaml.SafeLoader):
    """SafeLoader refusing a key given twice in a mapping (naming both lines)."""


def _mapping(loader, node, deep=False):
    seen = {}
    for k, _ in node.value:
        key = loader.construct_object(k, deep=deep)
        if key in seen:
            raise InputError("%s:%d: entry '%s' given twice (first on line %d)"
                             % (loader.name, k.start_mark.line + 1, key, seen[key]))
        seen[key] = k.start_mark.line + 1
    return loader.construct_mapping(node, deep=deep)


StrictLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _mapping)


def _lines(text):
    """{top-level key: its line} of a YAML text."""
    node = yaml.compose(text, Loader=yaml.SafeLoader)
    return {k.value: k.start_mark.line + 1 for k, _ in node.value} if node is not None else {}


class Description:
    """The description's drum-model sections (dicts, as written), the study's
    settings (defaults filled in) and what was left to defaults (for the report)."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        if not os.path.isfile(self.path):
            raise InputError("%s: no such file" % path)
        try:
            with open(self.path, encoding="utf-8") as f:
                text = f.read()
        except UnicodeDecodeError as e:
            raise InputError("%s: not UTF-8 text (byte %d)" % (path, e.start))
        try:
            loader = StrictLoader(text)
            loader.name = self.path
            data = loader.get_single_data()
            lines = _lines(text)
        except yaml.YAMLError as e:
            raise InputError("%s: not YAML: %s" % (self.path, str(e).replace("\n", " ")))
        if not isinstance(data, dict):
            raise InputError("%s: a description is a dictionary of sections (drum, flights, material, gas, "
                             "study)" % self.path)
        allowed = DRUM_SECTIONS + ("study",)
        for key in data:
            if key not in allowed:
                near = difflib.get_close_matches(str(key), allowed, 1, 0.6)
                raise InputError("%s:%s: unknown section '%s'%s; allowed: %s"
                                 % (self.path, lines.get(key, "?"), key,
                                    " (did you mean '%s'?)" % near[0] if near else "", " ".join(allowed)))
        for key in ("drum", "flights", "material", "gas"):
            if not isinstance(data.get(key), dict):
                raise InputError("%s: section '%s' is missing (the drum model's; see drumSolver's README)"
                                 % (self.path, key))
        self.lines = lines
        self.sections = {k: data[k] for k in DRUM_SECTIONS if k in data}
        self.defaults = []          # (entry, value, meaning): what the description left to defaults
        self.study = self._study(data.get("study") or {})
        self._model()
        self._rtd()
        from .segment import check, table_kind
        if self.study["table"] and table_kind(self.study["table"]) == "segment":
            check(self, sweep=False)
        elif self.study["scene"] == "drumSegment":
            check(self)

    def where(self, entry):
        return "%s:%s: entry '%s'" % (self.path, self.lines.get(entry.split(".")[0], "?"), entry)

    def _study(self, given):
        if not isinstance(given, dict):
            raise InputError("%s must be a dictionary" % self.where("study"))
        out = {}
        for key in given:
            if key not in STUDY_KEYS:
                near = difflib.get_close_matches(str(key), list(STUDY_KEYS), 1, 0.6)
                raise InputError("%s: unknown%s; allowed: %s" % (self.where("study." + str(key)),
                                 " (did you mean 'study.%s'?)" % near[0] if near else "", " ".join(STUDY_KEYS)))
        for key, (default, check, meaning) in STUDY_KEYS.items():
            if key not in given:
                out[key] = default
                if default is not None:
                    self.defaults.append(("study." + key, default, meaning))
                continue
            v = given[key]
            if check == "dragLaws":
                check = facts.drag_laws()
            if isinstance(check, tuple) and check and isinstance(check[0], str):
                if v not in check:
                    raise InputError("%s = '%s' is not one of %s" % (self.where("study." + key), v, " ".join(check)))
            elif isinstance(check, tuple):
                if isinstance(v, bool) or not isinstance(v, (int, float)) or not check[0] <= v <= check[1]:
                    raise InputError("%s = %s outside the allowed range [%g, %g]"
                                     % (self.where("study." + key), v, check[0], check[1]))
            elif key == "curve":
                v = self._curve(v)
            elif key == "table":
                v = os.path.normpath(os.path.join(PROJECT if str(v).startswith("$DRYER_PROJECT") else
                                                  os.path.dirname(self.path),
                                                  str(v).replace("$DRYER_PROJECT/", "")))
                if not os.path.isfile(v):
                    raise InputError("%s: no such table %s" % (self.where("study.table"), v))
            out[key] = v
        if out["scene"] != "drumSegment":
            # the stop is the drum segment's (a box stops when its drift is steady)
            if "stop" in given:
                raise InputError("%s belongs to scene drumSegment (a box curtain stops when its drift is steady)"
                                 % self.where("study.stop"))
            self.defaults = [x for x in self.defaults if x[0] != "study.stop"]
        if out["scene"] == "drumSegment" and "iterations" not in given:
            # a drum segment's cap is its template's (it stops when its means are known)
            out["iterations"] = None
            self.defaults = [x for x in self.defaults if x[0] != "study.iterations"]
            self.defaults.append(("study.iterations", "the segment template's cap",
                                  "local steps a drum segment may take (it stops when its means are known)"))
        return out

    def _curve(self, v):
        """study.curve: {entry: SECTION.KEY, values: [...]}: the entry one the drum
        model has in this description, 2 to 20 numbers."""
        if not isinstance(v, dict) or set(v) != {"entry", "values"}:
            raise InputError("%s must be {entry: SECTION.KEY, values: [v1, v2, ...]}" % self.where("study.curve"))
        entry, values = v["entry"], v["values"]
        if entry not in CURVE_ENTRIES:
            raise InputError("%s = '%s' is not one of %s" % (self.where("study.curve.entry"), entry,
                                                             " ".join(CURVE_ENTRIES)))
        section, key = entry.split(".")
        if not isinstance(self.sections.get(section), dict) or key not in self.sections[section]:
            raise InputError("%s = '%s': the description has no %s to vary" % (self.where("study.curve.entry"),
                                                                              entry, entry))
        if (not isinstance(values, list) or not 2 <= len(values) <= 20
                or not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in values)):
            raise InputError("%s must be a list of 2 to 20 numbers" % self.where("study.curve.values"))
        return {"entry": entry, "values": [float(x) for x in values]}

    def _model(self):
        m = self.sections.get("model")
        if m is None:
            twoPhase = isinstance(self.sections["flights"], dict) and "exterior" in self.sections["flights"]
            m = {"type": "twoPhase"} if twoPhase else dict(COMPARTMENT_DEFAULTS)
            self.defaults.append(("model", m, "the drum model (none given)"))
            self.sections["model"] = m
        elif not isinstance(m, dict):
            raise InputError("%s must be a dictionary" % self.where("model"))
        if "drift" in m:
            raise InputError("%s: the study sets the drift per route (CFD table, Eq 142, lone particles): "
                             "remove it" % self.where("model.drift"))

    def _rtd(self):
        r = self.sections.get("rtd")
        if r is None:
            r = dict(RTD_DEFAULTS)
            self.defaults.append(("rtd", r, "the residence time distribution's integration"))
            self.sections["rtd"] = r
        elif not isinstance(r, dict):
            raise InputError("%s must be a dictionary" % self.where("rtd"))
        tracer = r.get("tracer")
        if isinstance(tracer, dict) and isinstance(tracer.get("file"), str):
            f = tracer["file"]
            if not f.startswith("$DRYER_"):
                tracer["file"] = os.path.normpath(os.path.join(os.path.dirname(self.path), f))

    def drum_dict(self, drift, drift_section, override=None):
        """The drumDict text of one route: the description's sections with
        model.drift and the drift section the route sets (and, on an operating
        curve, override = (SECTION.KEY, value))."""
        sections = {k: (dict(v) if isinstance(v, dict) else v) for k, v in self.sections.items()}
        if override:
            section, key = override[0].split(".")
            value = override[1]
            sections[section][key] = int(value) if key == "count" else value
        sections["model"]["drift"] = drift
        if drift_section:
            sections["drift"] = drift_section
        head = "# written by dryerStudy from %s: do not edit (edit the description)\n" % self.path
        return head + yaml.safe_dump(sections, sort_keys=False, default_flow_style=None)

    def tracer(self):
        return isinstance(self.sections["rtd"].get("tracer"), dict)
