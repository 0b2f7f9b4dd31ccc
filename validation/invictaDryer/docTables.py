"""docTables: the Invicta comparison's tables in docs/validation.md and the
README, written from the physics case's results (docs/figures -update calls
them). Each function takes a docFigures.Results and returns Markdown."""

from flightedDryer import docFigures as df

CASE = "cases/invictaDryer/physics"
TRACER = CASE + "/results/tracerComparison.csv"
ROUTES = CASE + "/routes.csv"
NAMES = {"t10_s": ("t10", "min"), "t50_s": ("t50", "min"), "t90_s": ("t90", "min"),
         "body_mean_s": ("mean of the body (before 20 min)", "min"),
         "body_std_s": ("SD of the body", "min"), "tail_share": ("share after 20 min", "%")}


def invictaTracer(results):
    """The physics case's RTD against the tracer, quantity by quantity, with the 5 % goal."""
    out = ["| quantity | model | tracer | model / tracer | within 5 % |", "|---|---|---|---|---|"]
    for r in results.rows(TRACER):
        name, unit = NAMES.get(r["quantity"], (r["quantity"], ""))
        scale, form = (1 / 60.0, "%.2f") if unit == "min" else (100.0, "%.1f")
        model = df.finite(r["model"], TRACER) * scale
        meas = df.finite(r["measured"], TRACER) * scale
        ratio = df.finite(r["model_over_measured"], TRACER)
        if r["within_goal"] not in ("yes", "no"):
            raise df.FigureError("%s: within_goal '%s' is not yes or no" % (TRACER, r["within_goal"]))
        out.append("| %s [%s] | %s | %s | %s | %s |" % (name, unit, df.fmt(model, form), df.fmt(meas, form),
                                                        df.fmt(ratio, "%.3f"), r["within_goal"]))
    return "\n".join(out)


def invictaRoutes(results):
    """Every route of the physics case: holdup, mean and SD against the measured ones."""
    out = ["| route | holdup [kg] | airborne | mean [min] | SD [min] | mean error | SD error |",
           "|---|---|---|---|---|---|---|"]
    for r in results.rows(ROUTES):
        v = lambda c: df.finite(r[c], ROUTES)
        out.append("| `%s`: %s | %s | %s %% | %s | %s | %s %% | %s %% |" % (
            r["route"], r["description"], df.fmt(v("holdup_kg"), "%.0f"), df.fmt(100 * v("airborne_fraction"), "%.1f"),
            df.fmt(v("exact_mean_min"), "%.2f"), df.fmt(v("exact_std_min"), "%.2f"),
            df.fmt(v("mean_error_pct"), "%+.1f"), df.fmt(v("std_error_pct"), "%+.1f")))
    return "\n".join(out)
