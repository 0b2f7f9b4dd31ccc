#!/bin/sh
# drumSolver end to end: the Invicta case runs and writes its results; bad
# input stops with an InputError naming file, entry and range.
# Usage: drumSolverCli.sh DRUMSOLVER CASE_DIR WORK_DIR
set -u
solver="$1"; src="$2"; work="$3"
fail() { echo "FAIL: $*"; exit 1; }
# (awk checks are written as !(ok) with strict comparisons only: mawk takes NaN as
# equal to anything, so <=, >= and == hold for it, and < and > do not)
rm -rf "$work"; mkdir -p "$work"
# the case names its tracer file as $DRYER_DATA/...: the copy runs anywhere
cp "$src/drumDict" "$work/drumDict"
"$solver" -case "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "Invicta case did not run"; }
for f in summary.csv rtd.csv profile.csv; do
    [ -s "$work/results/$f" ] || fail "results/$f missing"
done
head -1 "$work/results/summary.csv" | grep -q "holdup_kg,airborne_fraction,mean_residence_time_s,rtd_std_s" || fail "summary columns"
head -1 "$work/results/rtd.csv" | grep -q "^time_s,E_per_s" || fail "rtd columns"
# Lee Table 7.3 (N = 33): mean 10.29 min; the run's mean within 1 %
awk -F, 'NR==2 { m = $3/60; if (!(m > 10.29*0.99 && m < 10.29*1.01)) { print "mean " m; exit 1 } }' \
    "$work/results/summary.csv" || fail "mean residence time off Table 7.3"
[ "$(ls "$work/results" | grep -c '\.tmp')" = 0 ] || fail "temporary files left"

bad() {  # bad <sed expression> <expected text in the error> (on $base, default Lee's case)
    cp "${base:-$work/drumDict}" "$work/bad/drumDict"
    sed -i "$1" "$work/bad/drumDict"
    if "$solver" -case "$work/bad" > "$work/bad/log" 2>&1; then
        fail "accepted: $1"
    fi
    grep -q "drumDict" "$work/bad/log" || { cat "$work/bad/log"; fail "error does not name the file ($1)"; }
    grep -q "$2" "$work/bad/log" || { cat "$work/bad/log"; fail "error does not say '$2' ($1)"; }
    [ ! -e "$work/bad/results/summary.csv" ] || fail "results written for bad input ($1)"
}
# partition flightModel (Lee's geometric flights + Sherritt drift)
mkdir -p "$work/flightModel"
sed -e 's/^  partition: leeCorrelations/  partition: flightModel/' -e 's/^  slices: 33/  slices: 20/' \
    -e '/^  backFraction:/d' -e '/^  forwardDragFactor:/d' "$work/drumDict" > "$work/flightModel/drumDict"
"$solver" -case "$work/flightModel" > "$work/flightModel/log" 2>&1 || { cat "$work/flightModel/log"; fail "flightModel case did not run"; }
[ -s "$work/flightModel/results/rtd.csv" ] || fail "flightModel rtd.csv missing"
sed -i 's/^  slices: 20/  slices: 200/' "$work/flightModel/drumDict"
if "$solver" -case "$work/flightModel" > "$work/flightModel/log" 2>&1; then fail "flightModel accepted 200 slices"; fi
grep -q "model.slices" "$work/flightModel/log" || fail "nearest-neighbour error does not name model.slices"
sed -i 's/^  slices: 200/  slices: 20/' "$work/flightModel/drumDict"
# flights that leave the bed full (flightHoldup bedFilled, pickup from each slice's bed): a fixed point of
# the flights' load and the bed; more holdup than Lee's mirrored Eq 4.21 load
mkdir -p "$work/bedFilled"
sed 's/^  partition: flightModel/&\n  flightHoldup: bedFilled/' "$work/flightModel/drumDict" > "$work/bedFilled/drumDict"
"$solver" -case "$work/bedFilled" > "$work/bedFilled/log" 2>&1 || { cat "$work/bedFilled/log"; fail "bedFilled case did not run"; }
grep -q "pockets under each slice's kilning bed full" "$work/bedFilled/log" || fail "bedFilled fixed point not reported"
paste -d, "$work/flightModel/results/summary.csv" "$work/bedFilled/results/summary.csv" | awk -F, 'NR==1 { n = NF/2 }
    NR==2 { if (!($(1 + n) > 1.2*$1)) { print $1, $(1 + n); exit 1 } }' || fail "bedFilled holdup not above the Eq 4.21 one"
awk -F, 'NR==1 { for (i = 1; i <= NF; ++i) c[$i] = i }
    NR > 1 { tp = $(c["passive_time_s"]); if (!(tp > 6 && tp < 15)) { print NR, tp; exit 1 } }' \
    "$work/bedFilled/results/profile.csv" || fail "bedFilled passive times outside 6-15 s"
mkdir -p "$work/bad"
base="$work/bedFilled/drumDict"
bad 's/^  flightHoldup: bedFilled/  flightHoldup: bedfilled/' "model.flightHoldup.*allowed: eq421, bedFilled"
bad 's/^  flightHoldup: bedFilled/&\n  flightPickup_deg: bedd/' "model.flightPickup_deg.*or bed"
bad 's/^  flightHoldup: bedFilled/&\n  flightPickup_deg: 85/' "model.flightPickup_deg.*range"
bad 's/^  flightHoldup: bedFilled/  flightPickup_deg: 10/' "model.flightPickup_deg': not used without model.flightHoldup bedFilled"
# size classes resolved: each class its own curtains in the shared slices; classes.csv per class,
# the fine class stays longer than the coarse one
mkdir -p "$work/classes"
sed -e 's/sizes_um: \[850\]/sizes_um: [500, 850, 1400]/' -e 's/fractions_pct: \[100\]/fractions_pct: [30, 40, 30]/' \
    -e 's/^  flightHoldup: bedFilled/&\n  sizeClasses: resolved/' -e 's/^  massRate: 0/  massRate: 20/' \
    "$work/bedFilled/drumDict" > "$work/classes/drumDict"
grep -q "^  massRate: 20" "$work/classes/drumDict" || fail "could not set the gas rate"
"$solver" -case "$work/classes" > "$work/classes/log" 2>&1 || { cat "$work/classes/log"; fail "sizeClasses resolved did not run"; }
grep -q "3 size classes resolved" "$work/classes/log" || fail "size classes not reported"
awk -F, 'NR==1 { for (i = 1; i <= NF; ++i) c[$i] = i } NR > 1 { t[NR - 1] = $(c["exact_mean_s"]) }
    END { if (NR != 4 || !(t[1] > t[2] && t[2] > t[3])) { print NR, t[1], t[2], t[3]; exit 1 } }' \
    "$work/classes/results/classes.csv" || fail "classes.csv: 3 classes, finer ones staying longer"
base="$work/classes/drumDict"
bad 's/^  sizeClasses: resolved/  sizeClasses: resolve/' "model.sizeClasses.*allowed: mixed, resolved"
bad 's/^  sizeClasses: resolved/&\n  denseDispersion: sherritt2001/' "model.denseDispersion.*not with model.sizeClasses resolved"
unset base
bad 's/^  partition: leeCorrelations/&\n  sizeClasses: resolved/' "model.sizeClasses': not used by partition leeCorrelations"
bad 's/^  partition: leeCorrelations/&\n  flightHoldup: bedFilled/' "model.flightHoldup': not used by partition leeCorrelations"

mkdir -p "$work/bad"
bad 's/feedRate: .*/feedRate: -3/' "material.feedRate.*range"
bad 's/^  massRate: 0/&\n  pressure_kPa: 5/' "gas.pressure_kPa.*range"
bad 's/feedRate: .*/feedRate: 0/' "material.feedRate.*range"
bad 's/slope_deg: .*/slope_deg: 35/' "drum.slope_deg.*range"
bad 's/speed_rpm: .*/speed_rpm: 0/' "drum.speed_rpm.*range"
bad 's/speed_rpm: .*/speed_rpm: 90/' "drum.speed_rpm.*range"
bad 's/type: compartment/type: plugFlow/' "model.type.*allowed: compartment, twoPhase"
bad 's#file: .*#file: /nonexistent/tracer.csv#' "rtd.tracer.file.*not found"
bad 's/integrator: exact/integrator: rk4/' "rtd.integrator.*allowed"
bad 's/backFraction: .*/backFraction: 0.95/' "C_F + C_B"
# the kilning bed from the rolling-bed equation (Sherritt 1991 Eq 22): no kiln time
mkdir -p "$work/saeman"
sed 's/^  kilnTime: .*/  kilnTime: saeman\n  kilnBedSlope_deg: profile/' "$work/drumDict" > "$work/saeman/drumDict"
"$solver" -case "$work/saeman" > "$work/saeman/log" 2>&1 || { cat "$work/saeman/log"; fail "kilnTime saeman did not run"; }
grep -q "rolling-bed equation" "$work/saeman/log" || fail "saeman kilning not reported"
awk -F, 'NR==1 { for (i = 1; i <= NF; ++i) c[$i] = i }
    NR==2 { t = $(c["kiln_time_s"]); m = $(c["kiln_mass_kg"]); if (!(t > 0 && t < 1e4 && m > 0)) { print t, m; exit 1 } }' \
    "$work/saeman/results/summary.csv" || fail "saeman: no implied kiln time"
bad 's/^  kilnTime: .*/  kilnTime: saemann/' "model.kilnTime.*or saeman"
bad 's/^  kilnTime: .*/  kilnTime: saeman\n  kilnBedSlope_deg: profiled/' "model.kilnBedSlope_deg.*or profile"
bad 's/^  kilnTime: .*/  kilnTime: 9.28\n  kilnBedSlope_deg: 1/' "model.kilnBedSlope_deg': not used without model.kilnTime saeman"
bad 's/^  kilnTime: .*/  kilnTime: saeman/; s/^rtd:/estimation: {parameters: [backFraction]}\nrtd:/' "not with model.kilnTime saeman"
# entries the chosen model or partition does not use are refused, not ignored
bad 's/^  partition: leeCorrelations/  partition: flightModel/' "entry 'model.backFraction': not used by partition flightModel"
bad 's/^  partition: leeCorrelations/&\n  drift: sherritt/' "entry 'model.drift': not used by partition leeCorrelations"
bad 's/^rtd:/drift: {outside: clamp}\nrtd:/' "entry 'drift': not used by partition leeCorrelations"
# passive-phase dispersion (model.denseDispersion for the compartment model)
bad 's/^  forwardDragFactor: .*/&\n  denseDispersion: -1/' "model.denseDispersion.*range"
bad 's/^  forwardDragFactor: .*/&\n  denseDispersion: sherritt2001\n  dispersionBed: bottom/' "model.dispersionBed.*allowed: kiln, passive"
bad 's/^  forwardDragFactor: .*/&\n  dispersionBed: passive/' "model.dispersionBed.*needs model.denseDispersion"
bad 's/^  forwardDragFactor: .*/&\n  denseDispersion: sherritt2001\nestimation: {parameters: [kilnTime]}/' "model.denseDispersion.*not with estimation"
# a strict dictionary: misspelt and duplicated keys, fractions for whole numbers,
# a list item that is not a number (each names the line and the entry)
bad 's/^  kilnTime:/  kilnTim:/' "drumDict:[0-9]*: entry 'model.kilnTim': unknown entry (did you mean 'model.kilnTime'?)"
bad 's/^rtd:/rtdd:/' "entry 'rtdd': unknown entry (did you mean 'rtd'?)"
bad 's/^  slices: 33/  slices: 33\n  slices: 20/' "entry 'model.slices': given twice (first on line"
bad 's/^  count: .*/  count: 28.7/' "entry 'flights.count': '28.7' is not a whole number"
bad 's/^  slices: 33/  slices: 33.5/' "entry 'model.slices': '33.5' is not a whole number"
bad 's/^  feedRate: .*/  feedRate: abc/' "entry 'material.feedRate': not a number"
bad 's/sizes_um: \[850\]/sizes_um: [abc]/' "entry 'material.sizes_um.0.': 'abc' is not a number"
mkdir -p "$work/dispersion"
sed 's/^  forwardDragFactor: .*/&\n  denseDispersion: sherritt2001/' "$work/drumDict" > "$work/dispersion/drumDict"
"$solver" -case "$work/dispersion" > "$work/dispersion/log" 2>&1 || { cat "$work/dispersion/log"; fail "sherritt2001 dispersion case did not run"; }
grep -q "rolling/cascading" "$work/dispersion/log" || fail "dispersion regime not reported"
grep -q "warning: passive dispersion: drum diameter" "$work/dispersion/log" || fail "no warning for the 5 m drum outside the fitted range"
# same mean (holdup theorem), wider RTD than Lee's network alone
paste -d, "$work/results/summary.csv" "$work/dispersion/results/summary.csv" | awk -F, 'NR==1 { for (i = 1; i <= NF; ++i) c[$i] = c[$i] ? c[$i] : i; n = NF/2 }
    NR==2 { m0 = $(c["exact_mean_s"]); s0 = $(c["exact_std_s"]); m1 = $(c["exact_mean_s"] + n); s1 = $(c["exact_std_s"] + n);
            if (!((m1 - m0)^2 < (1e-6*m0)^2 && s1 > s0)) { print m0, m1, s0, s1; exit 1 } }' || fail "dispersion changed the mean or did not widen the RTD"
# forward Euler beyond its stable step: a clear error, no silent answer
bad 's/integrator: exact/integrator: forwardEuler/' "forward Euler is unstable"
# model twoPhase (Sherritt 1991) on Sheikh's drum (Sherritt Table 5.1)
mkdir -p "$work/twoPhase"
cat > "$work/twoPhase/drumDict" <<'DICT'
drum: {length: 2.10, diameter: 0.385, slope_deg: 1.0, speed_rpm: 5.7}
flights: {count: 12, baseLength: 0.04, tipLength: 0.04, baseAngle_deg: 90, tipAngle_deg: 90}
material:
  feedRate: 0.02
  bulkDensity: 1517
  particleDensity: 2650
  repose_deg: 35.69
  sizes_um: [707, 421, 326, 252, 163, 88]
  fractions_pct: [11.6, 21.6, 12.0, 29.6, 22.1, 3.2]
gas: {flow: coCurrent, massRate: 0}
model: {type: twoPhase, drift: sherritt}
DICT
"$solver" -case "$work/twoPhase" > "$work/twoPhase/log" 2>&1 || { cat "$work/twoPhase/log"; fail "twoPhase case did not run"; }
head -1 "$work/twoPhase/results/summary.csv" | grep -q "^holdup_kg,airborne_fraction,mean_residence_time_s,rtd_std_s" || fail "twoPhase summary"
# T = holdup/feed (Sherritt Eq 31)
awk -F, 'NR==2 { r = $1/0.02/$3; if (!(r > 0.999 && r < 1.001)) { print r; exit 1 } }' "$work/twoPhase/results/summary.csv" \
    || fail "twoPhase T != H/F"
# the gas's pressure reaches the model: the same cocurrent gas mass rate at half an
# atmosphere is twice as fast and carries the solids further (shorter residence time)
for p in 101.325 50; do
    mkdir -p "$work/twoPhase_p$p"
    sed "s/^gas: .*/gas: {flow: coCurrent, massRate: 0.02, pressure_kPa: $p}/" "$work/twoPhase/drumDict" \
        > "$work/twoPhase_p$p/drumDict"
    "$solver" -case "$work/twoPhase_p$p" > "$work/twoPhase_p$p/log" 2>&1 || { cat "$work/twoPhase_p$p/log"; fail "twoPhase at $p kPa did not run"; }
done
paste -d, "$work/twoPhase_p101.325/results/summary.csv" "$work/twoPhase_p50/results/summary.csv" | awk -F, 'NR==1 { n = NF/2 }
    NR==2 { if (!($(3 + n) < 0.95*$3)) { print $3, $(3 + n); exit 1 } }' || fail "twoPhase: 50 kPa gas did not shorten the residence time"
sed -i 's/repose_deg: 35.69/moisture: {inlet: 0.01, outlet: 0.001}/' "$work/twoPhase/drumDict"
rm -rf "$work/twoPhase/results"
if "$solver" -case "$work/twoPhase" > "$work/twoPhase/log" 2>&1; then fail "twoPhase accepted a moisture profile"; fi
grep -q "material.repose_deg" "$work/twoPhase/log" || fail "twoPhase error does not name material.repose_deg"
sed -i 's/^  moisture: .*/  repose_deg: 35.69\n&/' "$work/twoPhase/drumDict"
if "$solver" -case "$work/twoPhase" > "$work/twoPhase/log" 2>&1; then fail "twoPhase accepted a moisture profile beside repose_deg"; fi
grep -q "entry 'material.moisture': not used by model.type twoPhase" "$work/twoPhase/log" || { cat "$work/twoPhase/log"; fail "twoPhase did not refuse material.moisture"; }
sed -i -e '/^  moisture: .*/d' -e 's/^model: .*/&\nestimation: {parameters: [kilnTime]}/' "$work/twoPhase/drumDict"
if "$solver" -case "$work/twoPhase" > "$work/twoPhase/log" 2>&1; then fail "twoPhase accepted an estimation section"; fi
grep -q "entry 'estimation': not used by model.type twoPhase" "$work/twoPhase/log" || { cat "$work/twoPhase/log"; fail "twoPhase did not refuse estimation"; }
echo "drumSolver CLI: all checks passed"
