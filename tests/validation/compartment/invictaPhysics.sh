#!/bin/sh
# The Invicta dryer from physics (cases/invictaDryer/physics): it runs in a
# copy anywhere (its table and tracer are named through $DRYER_PROJECT and
# $DRYER_DATA), the bed-filled flights settle with the bed, every size class
# passes and the finer classes stay longer (the counter-current gas holds them
# back), the mixture's mean is its holdup over the feed, and the case's
# headline (mean short of the measured 11.08 min by less than 15 %, SD well
# short of the measured 6.73 min, as its README says) holds.
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
            if (!((m - h - 19.8)^2 < 1e-6)) { print "mean " m " vs holdup/feed + pulse/2 " h + 19.8; exit 1 }
            if (!(m > 0.85*mm && m < mm)) { print "mean " m " s, measured " mm " s"; exit 1 }
            if (!(s < 0.5*ms)) { print "SD " s " s, measured " ms " s"; exit 1 } }' \
    "$work/results/summary.csv" || fail "physics case summary"
echo "Invicta physics case: all checks passed"
