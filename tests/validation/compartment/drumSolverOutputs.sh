#!/bin/sh
# drumSolver's outputs are whole or absent, never mixed: a rerun keeps the
# user's files in results/ and replaces the rest; a failed rerun leaves
# results/ as it was; on a full disk (a small tmpfs: needs root, as CI runs)
# the run exits 1 and leaves no partial folder, temporary or truncated file.
# Usage: drumSolverOutputs.sh DRUMSOLVER CASE_DIR WORK_DIR
set -u
solver="$1"; src="$2"; work="$3"
fail() { echo "FAIL: $*"; [ -n "${mnt:-}" ] && umount "$mnt" 2>/dev/null; exit 1; }
pass() { echo "PASS: $*"; }
sums() { (cd "$1" && find . -type f | sort | xargs md5sum); }
rm -rf "$work"; mkdir -p "$work/case"
cp "$src/drumDict" "$work/case/drumDict"
"$solver" -case "$work/case" > "$work/log.1" 2>&1 || { cat "$work/log.1"; fail "first run"; }
[ -f "$work/case/results/.written" ] || fail "no manifest"
echo "mine" > "$work/case/results/notes.txt"
mkdir -p "$work/case/results/plots" && echo x > "$work/case/results/plots/my.gp"
sed -i 's/^  slices: 33/  slices: 20/' "$work/case/drumDict"
"$solver" -case "$work/case" > "$work/log.2" 2>&1 || { cat "$work/log.2"; fail "second run"; }
[ "$(cat "$work/case/results/notes.txt")" = mine ] && [ -f "$work/case/results/plots/my.gp" ] \
    || fail "user files lost"
grep -q "kept your file .*notes.txt" "$work/log.2" || fail "kept files not reported"
grep -q "notes.txt" "$work/case/results/.written" && fail "a user file listed as written"
ls -a "$work/case" | grep -q "^\.results" && fail "partial or old results folder left"
pass "a rerun keeps the user's files and replaces the rest"

before=$(sums "$work/case/results")
sed -i 's/^  speed_rpm: .*/  speed_rpm: 90/' "$work/case/drumDict"
"$solver" -case "$work/case" > "$work/log.3" 2>&1 && fail "bad rerun accepted"
[ "$before" = "$(sums "$work/case/results")" ] || fail "a failed rerun changed results/"
pass "a failed rerun leaves results/ as it was"

[ "$(id -u)" = 0 ] || fail "the full-disk check needs root (mount -t tmpfs), as in CI"
cp "$src/drumDict" "$work/ref.drumDict"
mkdir -p "$work/ref" && cp "$src/drumDict" "$work/ref/drumDict"
"$solver" -case "$work/ref" > "$work/log.ref" 2>&1 || fail "reference run"
mnt="$work/full"; mkdir -p "$mnt"
failed=0; ran=0
for size in 16k 48k 96k 160k 1m; do
    mount -t tmpfs -o size=$size tmpfs "$mnt" || fail "mount tmpfs"
    cp "$src/drumDict" "$mnt/drumDict"
    if "$solver" -case "$mnt" > "$work/log.$size" 2>&1; then
        for f in $(cd "$work/ref/results" && ls *.csv); do
            cmp -s "$work/ref/results/$f" "$mnt/results/$f" || fail "$size: exit 0 but $f differs"
        done
        ran=$((ran + 1))
    else
        grep -q "cannot write" "$work/log.$size" || { cat "$work/log.$size"; fail "$size: no write error named"; }
        [ ! -e "$mnt/results" ] || fail "$size: a results folder was left by a failed run"
        [ -z "$(find "$mnt" -name '.*' ! -name '.' | head -1)" ] || fail "$size: hidden leftovers: $(find "$mnt" -name '.*')"
        failed=$((failed + 1))
        echo "   $size: $(tail -1 "$work/log.$size" | cut -c1-150)"
    fi
    umount "$mnt" || fail "umount"
done
mnt=""
[ $failed -ge 1 ] && [ $ran -ge 1 ] || fail "sizes: $failed failed, $ran ran (need both)"
pass "a full disk: exit 1, nothing partial left ($failed of 5 sizes failed, $ran ran)"
