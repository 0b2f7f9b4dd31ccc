#!/bin/bash
# drumSolver leaves nothing behind and names the user's folder:
#  - a hidden .results.partial<PID> of a killed run (its process gone) is removed by
#    the next run, one of a live run is not; a swap a killed run had begun (its old
#    folder renamed away, the new one complete) is finished, then replaced;
#  - SIGKILL of a running drumSolver, then a rerun: no hidden folder is left;
#  - a read-only or full disk: the error names results/, never the hidden folder.
# Usage: drumSolverLeftovers.sh DRUMSOLVER CASE_DIR WORK_DIR   (the full-disk part needs root)
set -u
solver="$1"; src="$2"; work="$3"
fail() { echo "FAIL: $*"; exit 1; }
pass() { echo "PASS: $*"; }
mounted=""
sleeper=""
cleanup() { [ -z "$mounted" ] || umount "$mounted" 2>/dev/null; [ -z "$sleeper" ] || kill "$sleeper" 2>/dev/null; }
trap cleanup EXIT
rm -rf "$work"; mkdir -p "$work/c"
cp "$src/drumDict" "$work/c/drumDict"
cd "$work"
hidden() { ls -a c | grep '^\.results\.' || true; }
deadPid() { sh -c 'echo $$'; }

# --- a killed run's partial folder: removed; a live run's: kept
dead=$(deadPid)
mkdir -p "c/.results.partial$dead/sub" && echo x > "c/.results.partial$dead/summary.csv"
sleep 600 & sleeper=$!
mkdir -p "c/.results.partial$sleeper" && echo y > "c/.results.partial$sleeper/summary.csv"
"$solver" -case c > log.1 2>&1 || { cat log.1; fail "run over leftovers"; }
grep -q "removed c/.results.partial$dead, left by a run that was killed" log.1 || { cat log.1; fail "no word of the removed folder"; }
[ ! -e "c/.results.partial$dead" ] || fail "a killed run's partial folder is still there"
[ -f "c/.results.partial$sleeper/summary.csv" ] || fail "a live run's partial folder was removed"
kill "$sleeper"; wait "$sleeper" 2>/dev/null; sleeper=""
rm -rf "c/.results.partial"*
[ -s c/results/summary.csv ] || fail "no results"
pass "a killed run's partial folder is removed, a live run's kept"

# --- a swap a killed run had begun: the old folder renamed away, the complete new one
# not yet in place; the next run finishes it (no results/ missing), then replaces it
cp c/results/summary.csv before.csv
echo "my notes" > c/results/notes.txt
"$solver" -case c > log.2 2>&1 || { cat log.2; fail "second run"; }
dead=$(deadPid)
mv c/results "c/.results.partial$dead"          # complete, with its manifest
mkdir "c/.results.old$dead" && cp "c/.results.partial$dead/.written" "c/.results.old$dead/"
cp "c/.results.partial$dead/summary.csv" "c/.results.old$dead/"
"$solver" -case c > log.3 2>&1 || { cat log.3; fail "run after an interrupted swap"; }
[ -z "$(hidden)" ] || fail "left after an interrupted swap: $(hidden)"
[ "$(cat c/results/notes.txt)" = "my notes" ] || fail "the user's file was lost in an interrupted swap"
cmp before.csv c/results/summary.csv || fail "results after an interrupted swap differ"
pass "an interrupted swap is finished and replaced; the user's file kept"

# --- SIGKILL while running (a slow tracer run), then a rerun: nothing hidden left
sed -e 's/^  timeStep: .*/  timeStep: 0.01/' -e 's/^  recovery: .*/  recovery: 0.999999/' c/drumDict > slow.yaml
mkdir -p s && cp slow.yaml s/drumDict
"$solver" -case s > log.s 2>&1 &
pid=$!
for _ in $(seq 1 400); do
    ls -a s | grep -q "^\.results\.partial$pid$" && break
    sleep 0.01
done
ls -a s | grep -q "^\.results\.partial$pid$" || { cat log.s; fail "the slow run ended before it could be killed"; }
sleep 0.3
kill -KILL "$pid"; wait "$pid" 2>/dev/null
ls -a s | grep -q "^\.results\.partial$pid$" || fail "the kill did not land inside the run"
cp c/drumDict s/drumDict
"$solver" -case s > log.s2 2>&1 || { cat log.s2; fail "rerun after SIGKILL"; }
[ -z "$(ls -a s | grep '^\.results\.')" ] || fail "left after a SIGKILL and a rerun: $(ls -a s | grep '^\.results\.')"
cmp before.csv s/results/summary.csv || fail "rerun after SIGKILL differs"
pass "SIGKILL mid-run: the rerun removes what it left and gives the same results"

# --- a read-only and a full disk: the error names results/, not the hidden folder
[ "$(id -u)" = 0 ] || fail "the disk checks need root (mount -t tmpfs), as in CI"
mkdir -p disk
for how in readOnly full; do
    if [ $how = full ]; then
        mount -t tmpfs -o size=48k tmpfs disk && mounted="$work/disk"
        mkdir disk/c && cp c/drumDict disk/c/
        head -c 40000 /dev/zero > disk/filler
    else
        mount -t tmpfs -o size=1m tmpfs disk && mounted="$work/disk"
        mkdir disk/c && cp c/drumDict disk/c/
        mount -o remount,ro disk
    fi
    if "$solver" -case disk/c > "log.$how" 2>&1; then fail "$how disk: exit 0"; fi
    grep -q "disk/c/results" "log.$how" || { cat "log.$how"; fail "$how disk: the error does not name disk/c/results"; }
    grep -q "\.results\.partial" "log.$how" && { cat "log.$how"; fail "$how disk: the error names the hidden folder"; }
    [ -z "$(ls -a disk/c | grep '^\.results\.')" ] || fail "$how disk: left $(ls -a disk/c)"
    echo "   $how: $(grep error "log.$how" | cut -c1-150)"
    umount disk && mounted=""
done
pass "a read-only and a full disk: the error names results/, nothing hidden left"
