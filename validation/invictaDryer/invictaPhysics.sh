#!/bin/sh
# The Invicta dryer from physics (cases/invictaDryer/physics): it runs in a
# copy anywhere (its table and tracer are named through $DRYER_PROJECT and
# $DRYER_DATA), the bed-filled flights settle with the bed, every size class
# passes and the finer classes stay longer (the counter-current gas holds them
# back), the mixture's mean is its holdup over the feed plus half the pulse,
# and the RTD is compared with the tracer, not with an earlier result: t10,
# t50, t90, the mean and SD of the body before 20 min and the share after it,
# model against measured, each against the goal (within 5 %). The tracer's own
# figures (body 9.92 / 2.46 min, 4.5 % after 20 min, from data/invicta_rtd.csv)
# must come out; the model's are reported with where they miss the goal, never
# pinned to today's shortfall.
# Usage: invictaPhysics.sh DRUMSOLVER CASE_DIR WORK_DIR
set -u
solver="$1"; src="$2"; work="$3"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"; mkdir -p "$work"
cp "$src/drumDict" "$work/drumDict"
"$solver" -case "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "physics case did not run"; }
grep -q "pockets under each slice's kilning bed full" "$work/log" || fail "bed-filled flights not reported"
grep -q "5 size classes resolved" "$work/log" || fail "size classes not resolved"
grep -q "warning" "$work/log" && { cat "$work/log"; fail "warnings (a clamp or a range) in the physics case"; }
awk -F, 'NR==1 { for (i = 1; i <= NF; ++i) c[$i] = i } NR > 1 { n++; t[n] = $(c["exact_mean_s"]); d[n] = $(c["diameter_um"]) }
    END { if (n != 5) { print "classes", n; exit 1 }
          for (k = 2; k <= n; ++k) if (!(d[k] > d[k-1] && t[k] < t[k-1])) { print k, d[k], t[k]; exit 1 } }' \
    "$work/results/classes.csv" || fail "classes.csv: five classes, each coarser one leaving sooner"
# the 39.6 s pulse shifts the tracer mean by half its length
awk -F, 'NR==1 { for (i = 1; i <= NF; ++i) c[$i] = i }
    NR==2 { m = $(c["exact_mean_s"]); h = $(c["holdup_over_feed_s"]); mm = $(c["measured_mean_s"]); s = $(c["exact_std_s"]); ms = $(c["measured_std_s"])
            if (!((m - h - 19.8)^2 < 1e-6)) { print "mean " m " vs holdup/feed + pulse/2 " h + 19.8; exit 1 } }' \
    "$work/results/summary.csv" || fail "physics case summary"
# against the tracer: the measured side is the tracer's own (its trapezoids on its samples)
cmp="$work/results/tracerComparison.csv"
[ -s "$cmp" ] || fail "no tracerComparison.csv"
. "$(dirname "$0")/../../tests/foam/testFunctions"
value() { awk -F, -v q="$1" -v c="$2" 'NR==1 { for (i = 1; i <= NF; ++i) k[$i] = i } $1 == q { print $k[c] }' "$cmp"; }
checkClose "measured body mean [min]" "$(calc "v/60" v="$(value body_mean_s measured)")" 9.915 0.005
checkClose "measured body SD [min]" "$(calc "v/60" v="$(value body_std_s measured)")" 2.459 0.005
checkClose "measured share after 20 min" "$(value tail_share measured)" 0.0448 0.0005
checkClose "measured t50 [min]" "$(calc "v/60" v="$(value t50_s measured)")" 9.66 0.01
n=0
for q in t10_s t50_s t90_s body_mean_s body_std_s tail_share; do
    a=$(value $q model); b=$(value $q measured); r=$(value $q model_over_measured); ok=$(value $q within_goal)
    checkExpr "a >= 0 && b > 0 && (r - a/b)^2 < 1e-12" "$q: model $a, measured $b, ratio $r" a="$a" b="$b" r="$r"
    case "$ok" in yes) ;; no) n=$((n + 1)) ;; *) fail "$q: within_goal '$ok'" ;; esac
    echo "   $q: model $a, measured $b, model/measured $r, within 5 %: $ok"
done
echo "Invicta physics case against the tracer: $n of 6 quantities outside the goal (reported, not pinned)"
echo "Invicta physics case: all checks passed"
