#!/bin/sh
# dataScatter reproduces the README's scatter figures (leave-one-out fit with
# material constants 0.278, near repeats 0.277, lone particle at the measured
# V_c 0.254 - the data README's 0.25), writes its CSV atomically, and a
# missing data folder is an error naming the file with nothing written.
# Usage: dataScatterTest.sh DATASCATTER WORK_DIR
set -u
script="$1"; work="$2"
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$script" -out "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "dataScatter exit $?"; }
csv="$work/dataScatter.csv"
[ -f "$csv" ] && [ ! -e "$csv.tmp" ] || fail "no $csv (or a .tmp left)"
val() { grep -F "$1" "$csv" | awk -F, '{print $NF}'; }
. "$(dirname "$0")/../../tests/foam/testFunctions"   # isFiniteNumber (mawk takes NaN as equal to anything)
near() { isFiniteNumber "$1" && isFiniteNumber "$2" && awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN{exit !((a-b)^2 <= t^2)}' \
    || fail "$4: $1, expected $2 +- $3"; }
near "$(val 'one constant per material (leave one out)')" 0.278 0.001 "material fit, leave one out"
near "$(val 'one constant per material (in sample)')" 0.250 0.001 "material fit, in sample"
near "$(val 'near-repeat pairs')" 0.277 0.001 "near repeats"
near "$(val 'measured V_c')" 0.254 0.001 "lone particle at V_c"
[ "$(grep -c 'leave one out' "$csv")" = 3 ] || fail "three fits"
# every leave-one-out RMS is above its in-sample RMS (a sanity check of the hat matrix)
awk -F, '/in sample/{i=$NF} /leave one out/{if (!($NF > i)) bad=1} END{exit bad}' "$csv" || fail "LOO below in-sample"
set +e
DRYER_DATA="$work/none" "$script" -out "$work/bad" > "$work/log.bad" 2>&1; rc=$?
set -e
[ $rc -ne 0 ] && grep -q "windtunnel_tests.csv not found" "$work/log.bad" || fail "missing data not reported"
[ ! -e "$work/bad/dataScatter.csv" ] || fail "output written without data"
echo "PASS: dataScatter"
