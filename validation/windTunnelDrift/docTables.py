"""docTables: the wind-tunnel validation's tables in docs/validation.md and
docs/driftScores.md, written from results/ (docs/figures -update calls them).

Each function takes a docFigures.Results (cached CSV reads below the checkout)
and returns Markdown. Scores are RMS of ln(predicted/measured), bias is the
mean ln, 'within' the share of rows within +-25 %. Every route carries its
label from routes.csv (how its inputs were chosen).
"""

import math
import os

from flightedDryer import docFigures as df

HERE = "validation/windTunnelDrift"
RES = HERE + "/results"
BREAKDOWN = RES + "/scoresBreakdown.csv"
SITE = RES + "/siteAir/scoresBreakdown.csv"
VC = RES + "/apparentVc/scoresBreakdown.csv"
VC_SITE = RES + "/apparentVc/siteAir/scoresBreakdown.csv"
MATERIALS = (("sand", "sand"), ("raw_shale", "raw shale"), ("spent_shale", "spent shale"))


def _f(v, form="%.3f"):
    return df.fmt(v, form)


def labels(results):
    """The labels of routes.csv ('# LABEL: meaning' lines) with the routes that carry each."""
    path = os.path.join(results.root, HERE, "routes.csv")
    with open(path, encoding="utf-8") as f:
        meanings = [line[1:].strip().split(": ", 1) for line in f
                    if line.startswith("# ") and ": " in line and not line.startswith("# How")]
    out = ["| label | meaning | routes |", "|---|---|---|"]
    for lab, meaning in meanings:
        routes = [r["model"] for r in results.rows(HERE + "/routes.csv") if r["label"] == lab]
        if not routes:
            raise df.FigureError("routes.csv: no route carries the label '%s'" % lab)
        out.append("| %s | %s | %s |" % (lab, meaning, ", ".join("`%s`" % r for r in routes)))
    unknown = {r["label"] for r in results.rows(HERE + "/routes.csv")} - {m[0] for m in meanings}
    if unknown:
        raise df.FigureError("routes.csv: labels without a meaning: %s" % ", ".join(sorted(unknown)))
    return "\n".join(out)


def label(results, model):
    """(label, description) of a route from routes.csv."""
    r = results.row(HERE + "/routes.csv", {"model": model})
    return r["label"], r["route"]


def _cell(results, file, model, group, value, with_bias=True, with_within=False):
    row = {"model": model, "group": group, "value": value}
    s = _f(results.value(file, row, "rms_ln"))
    if with_bias:
        s += " / " + _f(results.value(file, row, "bias_ln"), "%+.2f")
    if with_within:
        s += " / " + _f(results.value(file, row, "within25*100"), "%.0f") + " %"
    return s


def _count(results, file, model, group, value):
    return int(df.finite(results.row(file, {"model": model, "group": group, "value": value})["count"],
                         file))


def _key(entry):
    """(file, model in the file, key in routes.csv) of a table entry."""
    file, model = entry
    return file, model, ("siteAir:" + model if file in (SITE, VC_SITE) and model.startswith("cv_") else model)


def _table(results, entries, columns, title):
    head = "| %s | inputs | %s |" % (title, " | ".join(c[0] for c in columns))
    out = [head, "|" + "---|" * (len(columns) + 2)]
    for entry in entries:
        file, model, key = _key(entry)
        lab, desc = label(results, key)
        cells = [fn(results, file, model) for _, fn in columns]
        out.append("| %s (`%s`) | %s | %s |" % (desc, key, lab, " | ".join(cells)))
    return "\n".join(out)


def _by(group, value, bias=True):
    return lambda r, f, m: _cell(r, f, m, group, value, bias)


ALL = ("all: RMS ln / bias / within ±25 %", lambda r, f, m: _cell(r, f, m, "all", "all", True, True))
BANDS = [ALL,
         ("6.6 m", _by("fall_height_m", "6.6")), ("10.3 m", _by("fall_height_m", "10.3")),
         ("V_g < 3 m/s", _by("vg_band", "<3")), ("V_g ≥ 3 m/s", _by("vg_band", ">=3"))]
BY_MATERIAL = [(name, _by("material", key)) for key, name in MATERIALS]

HEADLINE = [(BREAKDOWN, "cv_height"), (BREAKDOWN, "cv_material"), (SITE, "cv_height"), (SITE, "cv_material"),
            (BREAKDOWN, "eq142_material"), (BREAKDOWN, "cfd_coarse"), (BREAKDOWN, "isolated"),
            (BREAKDOWN, "sherritt"), (SITE, "tableMaterial_p89")]
EVERY = HEADLINE[:-1] + [
            (BREAKDOWN, "cfd_coarse_kOmegaSST"), (BREAKDOWN, "cfd_coarse_layerpacked"),
            (SITE, "cfd_coarse_p89"), (SITE, "cfd_coarse_layerpacked_p89"),
            (SITE, "cfd_coarse_kOmegaSST_layerpacked_p89"), (SITE, "cfd_coarse_realizableKE_layerpacked_p89"),
            (SITE, "tableMaterial_p89"), (SITE, "tableMaterial_p89_landed"), (SITE, "tableVcMaterial_p89"),
            (BREAKDOWN, "tableMaterial"), (BREAKDOWN, "tableMaterial_landed"), (BREAKDOWN, "tableVcMaterial"),
            (BREAKDOWN, "table"), (BREAKDOWN, "table_landed"), (BREAKDOWN, "tableVc"),
            (BREAKDOWN, "porousSheet"), (BREAKDOWN, "porousSheetMaterials"),
            (SITE, "isolated_p89"), (SITE, "sherritt_p89")]


def headline(results):
    """The out-of-sample routes, the shipped closure, Eq 142 as published and the
    best post-hoc route on the bulk advance: all rows, by fall height and V_g band."""
    return _table(results, HEADLINE, BANDS, "route (bulk advance, 69 rows)")


def everyRoute(results):
    """Every route on the bulk advance: all rows, by fall height and V_g band."""
    return _table(results, EVERY, BANDS, "route (bulk advance, 69 rows)")


def byMaterial(results):
    """Every route by material (RMS ln / bias)."""
    return _table(results, EVERY, BY_MATERIAL, "route (bulk advance)")


CLOSURE_RUNS = ["cfd_coarse", "cfd_coarse_Simonin", "cfd_coarse_SimoninCrowe_Cp1", "cfd_coarse_kOmegaSST",
                "cfd_coarse_kOmegaSST_Simonin", "cfd_coarse_kOmegaSST_SimoninCrowe_Cp1",
                "cfd_coarse_realizableKE", "cfd_coarse_realizableKE_Simonin",
                "cfd_coarse_realizableKE_SimoninCrowe_Cp1", "cfd_coarse_Syamlal", "cfd_coarse_layerpacked"]


def _wall(results, model):
    return _f(results.value(RES + "/timing.csv", {"model": model}, "wall_s_per_row"), "%.1f") + " s"


def closures(results):
    """Every 69-row closure at 1 atm with its wall time per row (two rows at a time)."""
    cols = BANDS + [("wall time per row", lambda r, f, m: _wall(r, m))]
    return _table(results, [(BREAKDOWN, m) for m in CLOSURE_RUNS], cols, "closure (bulk advance, 69 rows)")


def closureMatrix(results):
    """Gas model against particle-turbulence modulation (RMS ln / bias)."""
    gases = (("k-epsilon", "cfd_coarse"), ("realizableKE", "cfd_coarse_realizableKE"),
             ("kOmegaSST", "cfd_coarse_kOmegaSST"))
    out = ["| gas model | no modulation | `Simonin` (drag sink) | `SimoninCrowe` Cp 1 (sink + wake production) |",
           "|---|---|---|---|"]
    for name, base in gases:
        cells = [_cell(results, BREAKDOWN, base + suffix, "all", "all")
                 for suffix in ("", "_Simonin", "_SimoninCrowe_Cp1")]
        out.append("| %s | %s |" % (name, " | ".join(cells)))
    return "\n".join(out)


def folds(results):
    """Each fold of each cross-validation: what the training rows chose and how it scores held out."""
    out = ["| candidates | protocol | held out | chosen | train RMS ln | held-out RMS ln |",
           "|---|---|---|---|---|---|"]
    for name, file in (("1 atm (eleven)", RES + "/crossValidation.csv"),
                       ("the tunnel's air (four)", RES + "/siteAir/crossValidation.csv")):
        for r in results.rows(file):
            if r["protocol"] not in ("fall_height", "material"):
                continue
            out.append("| %s | %s | %s | `%s` | %s | %s |" % (
                name, r["protocol"].replace("_", " "), r["held_out"].replace("_", " "), r["chosen"],
                _f(df.finite(r["train_rms_ln"], file)), _f(df.finite(r["held_out_rms_ln"], file))))
    return "\n".join(out)


SCALING = [(RES + "/scaling.csv", "cfd_coarse"), (RES + "/scaling.csv", "cfd_coarse_realizableKE"),
           (RES + "/scaling.csv", "cfd_coarse_kOmegaSST"), (RES + "/scaling.csv", "cfd_coarse_Simonin"),
           (RES + "/scaling.csv", "cfd_coarse_SimoninCrowe_Cp1"), (RES + "/scaling.csv", "table"),
           (RES + "/scaling.csv", "tableMaterial"), (RES + "/siteAir/scaling.csv", "tableMaterial_p89"),
           (RES + "/scaling.csv", "sherritt")]


def _scaling(results, file, rows):
    exps = ("vg", "spill", "L", "y")
    out = ["| | inputs | b_vg | b_spill | b_L | b_y | RMS ln less each material's mean error |",
           "|---|---|---|---|---|---|---|"]
    meas = {"model": "measured"}
    out.append("| measured (± standard error) | data | %s | – |" % " | ".join(
        "%s ± %s" % (_f(results.value(file, meas, "b_" + e), "%.2f"), _f(results.value(file, meas, "se_" + e), "%.2f"))
        for e in exps))
    for f, model in rows:
        lab, desc = label(results, model)
        out.append("| %s (`%s`) | %s | %s | %s |" % (
            desc, model, lab, " | ".join(_f(results.value(f, {"model": model}, "b_" + e), "%.2f") for e in exps),
            _f(results.value(f, {"model": model}, "rms_ln_less_material_bias"))))
    return "\n".join(out)


def scaling(results):
    """Power-law exponents with a constant per material, measured and per route (bulk advance)."""
    return _scaling(results, RES + "/scaling.csv", SCALING)


def scalingVc(results):
    """The same on the apparent in-sheet velocity."""
    f = RES + "/apparentVc/scaling.csv"
    return _scaling(results, f, [(f, m) for m in ("cfd_coarse", "cfd_coarse_kOmegaSST", "tableMaterial",
                                                   "table", "sherritt")])


VC_ROUTES = [(VC, "cv_height"), (VC, "cfd_coarse"), (VC, "cfd_coarse_p89"), (VC, "cfd_coarse_layerpacked_p89"),
             (VC, "eq142_material"), (VC, "isolated"), (VC, "sherritt"),
             (VC, "cfd_coarse_kOmegaSST"), (VC, "cfd_coarse_kOmegaSST_layerpacked_p89"),
             (VC, "cfd_coarse_realizableKE_layerpacked_p89"), (VC, "tableMaterial"), (VC, "tableMaterial_p89"),
             (VC, "table"), (VC, "tableVcMaterial"), (VC, "porousSheet")]


def apparentVc(results):
    """Every route on the apparent in-sheet velocity V_c (Eq 141; 67 rows)."""
    return _table(results, VC_ROUTES, BANDS + BY_MATERIAL, "route (apparent V_c, 67 rows)")


def dataScatter(results):
    """What any model can reach on these data."""
    f = RES + "/dataScatter.csv"
    out = ["| estimate | rows | parameters | RMS ln |", "|---|---|---|---|"]
    for r in results.rows(f):
        out.append("| %s | %s | %s | %s |" % (r["estimate"], r["rows"], r["parameters"],
                                             _f(df.finite(r["rms_ln"], f))))
    return "\n".join(out)


def oneCurtain(results):
    """Test 26 under four closures."""
    f = RES + "/closureOneCurtain.csv"
    out = ["| closure | bulk drift [m] | captured | V_c/V_g | measured [m] |", "|---|---|---|---|---|"]
    for r in results.rows(f):
        out.append("| %s | %s | %s | %s | %s |" % (
            r["closure"], _f(df.finite(r["drift_m"], f)), _f(df.finite(r["captured_fraction"], f), "%.2f"),
            _f(df.finite(r["vc_over_vg"], f)), _f(df.finite(r["measured_m"], f))))
    return "\n".join(out)


def _predictions(results, name):
    f = RES + "/predictions/%s.csv" % name
    return {r["test"]: df.finite(r["mean_advance_m"], f) for r in results.rows(f)}


def sensitivities(results):
    """Stated inputs varied on the 12 spread rows (kOmegaSST gas), against the same rows at the defaults."""
    base = _predictions(results, "cfd_coarse_kOmegaSST")
    out = ["| input varied (`score -cfd 12 -turbulence kOmegaSST ...`) | rows | ln change of the advance: mean (min to max) | RMS ln against measured: varied (default, same rows) |",
           "|---|---|---|---|"]
    for name, what in (("cfd_coarse_kOmegaSST_sieve18.5", "bottom sieve bin's lower bound 37 → 18.5 µm (`-sieveBottom 18.5`)"),
                       ("cfd_coarse_kOmegaSST_v0.67", "release velocity 1 → 0.67 m/s (`-releaseVelocity 0.67`)"),
                       ("cfd_coarse_kOmegaSST_v1.67", "release velocity 1 → 1.67 m/s (`-releaseVelocity 1.67`)")):
        var = _predictions(results, name)
        d = [math.log(var[t] / base[t]) for t in var]
        if not d:
            raise df.FigureError("%s: no rows" % name)
        rows = RES + "/scores_%sRows.csv" % name
        out.append("| %s | %d | %s (%s to %s) | %s (%s) |" % (
            what, len(d), _f(100 * (math.exp(sum(d) / len(d)) - 1), "%+.1f") + " %",
            _f(100 * (math.exp(min(d)) - 1), "%+.1f") + " %", _f(100 * (math.exp(max(d)) - 1), "%+.1f") + " %",
            _f(results.value(rows, {"model": name, "fall_height_m": "all"}, "rms_ln")),
            _f(results.value(rows, {"model": "cfd_coarse_kOmegaSST", "fall_height_m": "all"}, "rms_ln"))))
    return "\n".join(out)


def spheres(results):
    """Lone spheres of sieve size read through Eq 141, against the tunnel's C_V, per material."""
    f = RES + "/sphereApparentVc.csv"
    out = ["| material | rows | tunnel's C_V: max (rows above 1) | spheres' C_V where Eq 141 finds one within 4 V_g: min to max (rows) | rows beyond 4 |",
           "|---|---|---|---|---|"]
    for key, name in MATERIALS:
        rows = [r for r in results.rows(f) if r["material"] == key]
        meas = [df.finite(r["cv_measured"], f) for r in rows if r["cv_measured"] != ""]
        sph = [df.finite(r["cv_sphere"], f) for r in rows if r["cv_sphere"] != ""]
        out.append("| %s | %d | %s (%d) | %s | %d |" % (
            name, len(rows), _f(max(meas), "%.2f"), sum(v > 1 for v in meas),
            "%s to %s (%d)" % (_f(min(sph), "%.1f"), _f(max(sph), "%.1f"), len(sph)) if sph else "none",
            len(rows) - len(sph)))
    return "\n".join(out)


SCORES = ["isolated", "sherritt", "eq142_material", "cfd_coarse", "table", "table_landed", "tableVc",
          "tableMaterial", "tableMaterial_landed", "tableMaterial_p89", "tableVcMaterial", "porousSheet",
          "porousSheetMaterials"]


def scores(results):
    """The fast models and the shipped per-row CFD: score, bias, share and time per prediction."""
    f = RES + "/scores.csv"
    out = ["| model | inputs | 6.6 m | 10.3 m | all | bias | within ±25 % | time per prediction |",
           "|---|---|---|---|---|---|---|---|"]
    for m in SCORES:
        lab, desc = label(results, m)
        src = f if any(r["model"] == m for r in results.rows(f)) else BREAKDOWN
        if src == f:
            v = lambda h, c, form="%.3f": _f(results.value(f, {"model": m, "fall_height_m": h}, c), form)
        else:
            grp = {"6.6": ("fall_height_m", "6.6"), "10.3": ("fall_height_m", "10.3"), "all": ("all", "all")}
            v = lambda h, c, form="%.3f": _f(results.value(BREAKDOWN, {"model": m, "group": grp[h][0],
                                                                       "value": grp[h][1]}, c), form)
        t = [r for r in results.rows(RES + "/timing.csv") if r["model"] == m]
        per = df.finite(t[0]["wall_s_per_row"], "timing.csv") if t else None
        time = "–" if per is None else (_f(per, "%.1f") + " s" if per >= 1 else _f(per * 1e3, "%.2f") + " ms")
        out.append("| `%s`: %s | %s | %s | %s | %s | %s | %s | %s |" % (
            m, desc, lab, v("6.6", "rms_ln"), v("10.3", "rms_ln"), v("all", "rms_ln"),
            v("all", "bias_ln", "%+.2f"), v("all", "within25*100", "%.0f") + " %", time))
    return "\n".join(out)



def twelveRows(results):
    """The per-row CFD on the 12 spread rows: the tunnel's collection rule against what landed,
    and closures measured by what landed, beside Eq 142 and the material tables on the same rows."""
    f = RES + "/scores_cfd_coarse_landedRows.csv"
    g = RES + "/scores_cfd_coarse_gradientDiffusion_landedRows.csv"
    out = ["| closure, measure | rows | RMS ln / bias / within ±25 % | same rows: Eq 142 / `tableMaterial` |",
           "|---|---|---|---|"]
    for model, what, file in (("cfd_coarse", "plain k-epsilon, the tunnel's collection rule", f),
                              ("cfd_coarse_landed", "plain k-epsilon, what landed", f),
                              ("cfd_coarse_Simonin_landed", "k-epsilon + Simonin's sink, what landed", f),
                              ("cfd_coarse_gradientDiffusion_landed",
                               "k-epsilon + turbulent dispersion, what landed (rows where every class reached the floor)", g)):
        v = lambda m, c, form="%.3f": _f(results.value(file, {"model": m, "fall_height_m": "all"}, c), form)
        n = int(df.finite(results.row(file, {"model": model, "fall_height_m": "all"})["count"], file))
        out.append("| %s (`%s`) | %d | %s / %s / %s %% | %s / %s |" % (
            what, model, n, v(model, "rms_ln"), v(model, "bias_ln", "%+.2f"), v(model, "within25*100", "%.0f"),
            v("sherritt", "rms_ln"), v("tableMaterial", "rms_ln")))
    return "\n".join(out)


BENCH = "tests/benchmarks/driftTable/results/driftTableBenchmark.csv"
BENCH_NAMES = (("BM_tableLookup6", "DriftTable lookup, 6 varied axes (64 corners; grid of the shipped sweep)"),
               ("BM_tableLookup4", "DriftTable lookup, 4 varied axes (16 corners)"),
               ("BM_tableDrift6", "`table` model"), ("BM_tableVcDrift6", "`tableVc` model (lookup + lone-particle fall)"),
               ("BM_isolated", "`isolated`"), ("BM_sherritt", "`sherritt`"), ("BM_porousSheet", "`porousSheet`"))


def queryCost(results):
    """CPU time per drift query, the median of Google Benchmark's repetitions."""
    out = ["| query | CPU time [ns] |", "|---|---|"]
    for name, what in BENCH_NAMES:
        r = results.row(BENCH, {"name": name + "_median"})
        if r.get("time_unit") != "ns":
            raise df.FigureError("%s: %s is in '%s', not ns" % (BENCH, name, r.get("time_unit")))
        out.append("| %s | %s |" % (what, _f(df.finite(r["cpu_time"], BENCH), "%.0f")))
    return "\n".join(out)


def invictaDrift(results):
    """The Invicta flightModel case with each drift model (cases/invictaDryer/driftComparison)."""
    f = "cases/invictaDryer/driftComparison/results.csv"
    out = ["| drift | holdup [kg] | airborne | mean residence [min] | RTD SD [min] |", "|---|---|---|---|---|"]
    rows = results.rows(f)
    for r in rows:
        v = lambda c: df.finite(r[c], f)
        out.append("| `%s` | %s | %s %% | %s | %s |" % (r["model"], _f(v("holdup_kg"), "%.0f"),
                                                      _f(100 * v("airborne_fraction"), "%.1f"),
                                                      _f(v("mean_residence_time_min"), "%.2f"), _f(v("rtd_std_min"), "%.2f")))
    meas = {(df.finite(r["measured_mean_min"], f), df.finite(r["measured_std_min"], f)) for r in rows}
    if len(meas) != 1:
        raise df.FigureError("%s: the rows disagree on the measured mean and SD" % f)
    (m, s), = meas
    out.append("| measured (Lee's tracer) | | | %s | %s |" % (_f(m, "%.2f"), _f(s, "%.2f")))
    return "\n".join(out)


SHALE = RES + "/shaleSensitivity"
SHALE_VARIANTS = ["cfd_coarse_rhoRule", "cfd_coarse_rhoRuleLow", "cfd_coarse_rhoRuleHigh",
                  "cfd_coarse_rhoRule_psi0.80", "cfd_coarse_rhoRule_psi0.65"]


def shaleSensitivity(results):
    """The shales' density (the rule's central value and range) and grain shape
    (Haider-Levenspiel sphericity), each a fixed input scored on the shared rows:
    all rows, by material, fall height and V_g band (RMS ln / bias)."""
    cols = [ALL] + BY_MATERIAL + BANDS[1:]
    entries = [(BREAKDOWN, "cfd_coarse")] + [(SHALE + "/scoresBreakdown.csv", m) for m in SHALE_VARIANTS]
    return _table(results, entries, cols, "route (bulk advance, 69 rows)")


def shaleFolds(results):
    """The cross-validations with the shale variants among the headline's 1 atm
    candidates, against the headline's own (held-out RMS ln / bias)."""
    out = ["| candidates | leave one fall height out (`cv_height`) | leave one material out (`cv_material`) |",
           "|---|---|---|"]
    for name, file in (("the headline's eleven", BREAKDOWN),
                       ("the eleven and the five shale variants", SHALE + "/scoresBreakdown.csv")):
        out.append("| %s | %s | %s |" % (name, _cell(results, file, "cv_height", "all", "all"),
                                         _cell(results, file, "cv_material", "all", "all")))
    chosen = sorted({r["chosen"] for r in results.rows(SHALE + "/crossValidation.csv")
                     if r["protocol"] in ("fall_height", "material")})
    out.append("")
    out.append("The folds chose %s." % ", ".join("`%s`" % c for c in chosen))
    return "\n".join(out)
